package raylab.grade;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

import raylab.course.JavaBuild;

/**
 * User ids of their own for the children (grader running as root): each box reserves one id of
 * {@link #COUNT} starting at {@link #BASE} by locking a file ({@code raylab-uids/<id>.lock} in the
 * system's temporary folder, a folder only root may enter), so two gradings at once, in one JVM
 * or two, never share one. No passwd entry is needed: the child runs under the bare number. With
 * its own id, RLIMIT_NPROC counts only that child's threads, its leftover processes can be found
 * by id, and what it left in the shared writable places ({@link #SHARED}) can be removed.
 */
final class UidSlots {
    /** First id of the range: above every id a distribution or systemd hands out, below 2^31. */
    static final int BASE = 1_900_000_000;
    /** Ids in the range. */
    static final int COUNT = 4096;
    /** The places every user may write on a usual Linux system, cleaned of a child's files at its end. */
    static final List<Path> SHARED = List.of(Path.of("/tmp"), Path.of("/var/tmp"), Path.of("/dev/shm"),
            Path.of("/run/lock"), Path.of("/dev/mqueue"));

    private UidSlots() {
    }

    /** One reserved id; {@link #release} frees it. */
    record Slot(int uid, FileChannel channel, FileLock lock, Path file) {
        void release() {
            try {
                lock.release();
                channel.close();
            } catch (IOException e) {
                // the lock goes with the channel
            }
        }
    }

    /** Whether this process's user namespace maps the whole range (else no id of its own: null from reserve). */
    static boolean rangeMapped() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/uid_map"))) {
                String[] f = line.trim().split("\\s+");
                long inside = Long.parseLong(f[0]);
                long n = Long.parseLong(f[2]);
                if (inside <= BASE && BASE + (long) COUNT <= inside + n) {
                    return true;
                }
            }
        } catch (IOException | RuntimeException e) {
            return false;
        }
        return false;
    }

    /** Reserves a free id, or null when none can be (not mapped, no lock folder, all taken). */
    static Slot reserve() {
        if (!rangeMapped()) {
            return null;
        }
        Path folder = Path.of(System.getProperty("java.io.tmpdir"), "raylab-uids");
        try {
            Files.createDirectories(folder);
            Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwx------"));
        } catch (IOException | UnsupportedOperationException e) {
            return null;
        }
        int start = ThreadLocalRandom.current().nextInt(COUNT);
        for (int i = 0; i < COUNT; i++) {
            int uid = BASE + (start + i) % COUNT;
            Path file = folder.resolve(uid + ".lock");
            FileChannel ch = null;
            try {
                ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                FileLock lock = ch.tryLock();
                if (lock != null) {
                    if (processesOf(uid)) {
                        // a child of a grading that ended without cleaning up: leave this id alone
                        lock.release();
                        ch.close();
                        continue;
                    }
                    return new Slot(uid, ch, lock, file);
                }
                ch.close();
            } catch (OverlappingFileLockException e) {
                closeQuietly(ch); // this JVM holds it already
            } catch (IOException e) {
                closeQuietly(ch);
                return null;
            }
        }
        return null;
    }

    private static void closeQuietly(FileChannel ch) {
        if (ch != null) {
            try {
                ch.close();
            } catch (IOException ignored) {
                // nothing to do
            }
        }
    }

    /** Whether any process runs under this id. */
    static boolean processesOf(int uid) {
        try (var s = Files.list(Path.of("/proc"))) {
            return s.filter(p -> p.getFileName().toString().chars().allMatch(Character::isDigit)).anyMatch(p -> {
                try {
                    return Integer.valueOf(uid).equals(Files.getAttribute(p, "unix:uid"));
                } catch (IOException | RuntimeException e) {
                    return false;
                }
            });
        } catch (IOException e) {
            return false;
        }
    }

    /** Deletes every file and folder owned by {@code uid} in the shared writable places (not following links). */
    static void removeFilesOf(int uid) {
        for (Path place : SHARED) {
            if (Files.isDirectory(place, LinkOption.NOFOLLOW_LINKS)) {
                removeOwned(place, uid);
            }
        }
    }

    static void removeOwned(Path place, int uid) {
        try {
            Files.walkFileTree(place, java.util.EnumSet.noneOf(java.nio.file.FileVisitOption.class), 16,
                    new SimpleFileVisitor<>() {
                        @Override
                        public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                            if (dir.equals(place)) {
                                return FileVisitResult.CONTINUE;
                            }
                            if (owned(dir, uid)) {
                                JavaBuild.deleteTreeQuietly(dir);
                                return FileVisitResult.SKIP_SUBTREE;
                            }
                            // The child can only have written into folders every user may write.
                            return worldWritable(dir) ? FileVisitResult.CONTINUE : FileVisitResult.SKIP_SUBTREE;
                        }

                        @Override
                        public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                            if (owned(file, uid)) {
                                try {
                                    Files.deleteIfExists(file);
                                } catch (IOException e) {
                                    // best effort
                                }
                            }
                            return FileVisitResult.CONTINUE;
                        }

                        @Override
                        public FileVisitResult visitFileFailed(Path file, IOException exc) {
                            return FileVisitResult.CONTINUE;
                        }
                    });
        } catch (IOException e) {
            // best effort
        }
    }

    private static boolean worldWritable(Path dir) {
        try {
            return Files.getPosixFilePermissions(dir, LinkOption.NOFOLLOW_LINKS)
                    .contains(java.nio.file.attribute.PosixFilePermission.OTHERS_WRITE);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    private static boolean owned(Path p, int uid) {
        try {
            return Integer.valueOf(uid).equals(Files.getAttribute(p, "unix:uid", LinkOption.NOFOLLOW_LINKS));
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }
}
