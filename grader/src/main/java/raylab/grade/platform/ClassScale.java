package raylab.grade.platform;

import java.io.IOException;
import java.io.InputStream;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.LinkedHashMap;
import java.util.Map;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * What {@code grade-all} needs to grade a class on one machine or many: how many gradings fit
 * side by side ({@link #defaultJobs}), which submissions a shard grades ({@link Shard}), a lock
 * per student folder ({@link Lock}) and a grading that ends with the process that started it
 * ({@link #dieWithParent}).
 */
public final class ClassScale {
    private ClassScale() {
    }

    /** Held by the {@code raylab grade} that writes a student folder, for its whole life. */
    public static final String GRADING_LOCK = ".raylab-grade.lock";

    /**
     * Memory one grading needs with room to spare: Gradescope's default container (768 MB), in
     * which a whole grading runs (grader/README.md: about 320 MB at its peak).
     */
    static final long BYTES_PER_JOB = 768L << 20;

    /**
     * Gradings side by side: one per core (a grading waits on its child JVMs part of the time,
     * and two of its milestones run at once only where the sandbox allows it), at most as many as
     * the available memory holds at {@link #BYTES_PER_JOB} each, at least one. The cores are the
     * JVM's (a container's CPU limit included), the memory the smaller of /proc/meminfo's
     * {@code MemAvailable} and a cgroup v2 limit.
     */
    static int defaultJobs() {
        return jobsFor(Runtime.getRuntime().availableProcessors(), availableMemory());
    }

    static int jobsFor(int cores, long availableBytes) {
        long byMemory = availableBytes <= 0 ? cores : availableBytes / BYTES_PER_JOB;
        return (int) Math.max(1, Math.min(cores, byMemory));
    }

    /** Bytes of memory available to new processes (−1 if unknown). */
    static long availableMemory() {
        long available = -1;
        try {
            for (String line : Files.readAllLines(Path.of("/proc/meminfo"))) {
                if (line.startsWith("MemAvailable:")) {
                    available = Long.parseLong(line.replaceAll("[^0-9]", "")) * 1024;
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux
        }
        try {
            String max = Files.readString(Path.of("/sys/fs/cgroup/memory.max")).strip();
            String current = Files.readString(Path.of("/sys/fs/cgroup/memory.current")).strip();
            if (!max.equals("max")) {
                long left = Long.parseLong(max) - Long.parseLong(current);
                available = available < 0 ? left : Math.min(available, left);
            }
        } catch (IOException | RuntimeException e) {
            // no cgroup v2 limit
        }
        return available;
    }

    /** Shard {@code k} of {@code n} (1 ≤ k ≤ n). */
    public record Shard(int k, int n) {
        public Shard {
            if (n < 1 || k < 1 || k > n) {
                throw new IllegalArgumentException("a shard is K/N with 1 <= K <= N, got " + k + "/" + n);
            }
        }

        /**
         * The submissions of this shard: of the entries in their (sorted) order, those at
         * positions k−1, k−1+n, k−1+2n, ...: the shards of one folder cover every entry once.
         */
        <V> Map<String, V> of(Map<String, V> sorted) {
            Map<String, V> m = new LinkedHashMap<>();
            int i = 0;
            for (Map.Entry<String, V> e : sorted.entrySet()) {
                if (i++ % n == k - 1) {
                    m.put(e.getKey(), e.getValue());
                }
            }
            return m;
        }

        @Override
        public String toString() {
            return k + "/" + n;
        }
    }

    /** Reads {@code --shard K/N}. */
    public static final class ShardConverter implements ITypeConverter<Shard> {
        @Override
        public Shard convert(String s) {
            String[] p = s.split("/", -1);
            try {
                if (p.length == 2) {
                    return new Shard(Integer.parseInt(p[0].strip()), Integer.parseInt(p[1].strip()));
                }
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException("--shard: " + (e instanceof NumberFormatException
                        ? "K/N with whole numbers, got '" + s + "'" : e.getMessage()));
            }
            throw new TypeConversionException("--shard: K/N (for example 3/8), got '" + s + "'");
        }
    }

    /**
     * An exclusive lock on a file, held by this process until {@link #close} or its end (the
     * kernel releases it however the process ends, {@code kill -9} included).
     */
    public static final class Lock implements AutoCloseable {
        private final FileChannel channel;
        private final FileLock lock;

        private Lock(FileChannel channel, FileLock lock) {
            this.channel = channel;
            this.lock = lock;
        }

        /** The lock, or null if another process (or this one) holds it. */
        public static Lock tryTake(Path file) throws IOException {
            FileChannel c = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            try {
                FileLock l = c.tryLock();
                if (l != null) {
                    return new Lock(c, l);
                }
            } catch (OverlappingFileLockException e) {
                // held in this JVM
            }
            c.close();
            return null;
        }

        /** The lock, waiting for it up to {@code millis} (a grading being stopped lets go), or null. */
        public static Lock take(Path file, long millis) throws IOException {
            long end = System.nanoTime() + millis * 1_000_000L;
            while (true) {
                Lock l = tryTake(file);
                if (l != null || System.nanoTime() > end) {
                    return l;
                }
                try {
                    Thread.sleep(100);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return null;
                }
            }
        }

        @Override
        public void close() throws IOException {
            try {
                lock.release();
            } finally {
                channel.close();
            }
        }
    }

    /**
     * Ends this process, and every process it started, as soon as its standard input reaches its
     * end: the parent holds the other end of that pipe and never writes to it, so it closes
     * exactly when the parent ends, however (a {@code kill -9} too). Java cannot ask the kernel
     * for a signal at the parent's death (Linux's {@code PR_SET_PDEATHSIG}); this is that, portably.
     */
    public static void dieWithParent(String who) {
        Thread t = new Thread(() -> {
            InputStream in = System.in;
            try {
                byte[] b = new byte[256];
                while (in.read(b) >= 0) {
                    // the parent writes nothing; whatever comes is ignored
                }
            } catch (IOException e) {
                // closed: the same
            }
            System.err.println(who + ": the process that started it ended; stopping");
            System.err.flush();
            ProcessHandle.current().descendants().forEach(ProcessHandle::destroyForcibly);
            Runtime.getRuntime().halt(1);
        }, "die-with-parent");
        t.setDaemon(true);
        t.start();
    }
}
