package raylab.render;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.LinkedHashSet;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;

import raylab.scene.Display;

/**
 * Reads and writes PNG files. Writing never leaves a partial or stray file:
 * <ul>
 * <li>the picture is encoded in memory first, then written to a hidden temporary file beside the
 * target ({@code .NAME.PID.RANDOM.tmp}) and renamed over the target in one atomic step, so the
 * target is either the old file or the whole new one;</li>
 * <li>on Ctrl-C, TERM or HUP a shutdown hook deletes the temporary file (and no rename happens
 * after it ran);</li>
 * <li>a KILL cannot be caught: it can leave the hidden temporary file only if it lands during
 * the few milliseconds the encoded bytes are written; the next write to the same target deletes
 * temporary files of processes that no longer exist;</li>
 * <li>javax.imageio's disk cache is off, so it leaves nothing in the temporary folder.</li>
 * </ul>
 */
public final class PngFiles {
    /**
     * Test hook (system property): pause this many milliseconds after each 4 KiB written, so that
     * a test can stop the JVM while the temporary file is being written (0 or absent = none).
     */
    static final String SLOW_WRITE_PROPERTY = "raylab.test.slowPngWriteMillis";

    private static final Object LOCK = new Object();
    /** Temporary files that exist now and must go if the JVM is stopped. */
    private static final Set<Path> PENDING = new LinkedHashSet<>();
    private static boolean hookInstalled;
    private static boolean shuttingDown;

    static {
        ImageIO.setUseCache(false);
    }

    private PngFiles() {
    }

    /** A target that cannot be written, with the reason, as one line. */
    public static final class OutputException extends IOException {
        private static final long serialVersionUID = 1L;

        OutputException(String oneLine) {
            super(oneLine);
        }
    }

    /**
     * Checks, before any work, that {@code target} can be written: it must be a new path or an
     * existing regular file (not a directory, device, pipe, socket or symbolic link), and its
     * folder must exist (unless {@code mayCreateFolder}) and accept a new file, which is tried.
     */
    public static void checkTarget(Path target, boolean mayCreateFolder) throws OutputException {
        String shown = Display.path(target);
        Path abs = target.toAbsolutePath().normalize();
        BasicFileAttributes a = attributes(abs);
        if (a != null) {
            if (a.isDirectory()) {
                throw new OutputException(shown + ": is a directory; give the name of a PNG file in it");
            }
            if (a.isSymbolicLink()) {
                throw new OutputException(shown + ": is a symbolic link; give the path of the file itself");
            }
            if (!a.isRegularFile()) {
                throw new OutputException(shown + ": is not a regular file (a device, pipe or socket);"
                        + " raylab writes images only to regular files or new paths");
            }
        }
        Path dir = abs.getParent();
        if (dir == null) {
            throw new OutputException(shown + ": not a file path");
        }
        Path probeIn = dir;
        if (!Files.isDirectory(dir)) {
            Path existing = dir;
            while (existing != null && !Files.exists(existing)) {
                existing = existing.getParent();
            }
            if (existing != null && !Files.isDirectory(existing)) {
                throw new OutputException(shown + ": cannot be written: " + Display.path(existing)
                        + " is not a directory");
            }
            if (!mayCreateFolder) {
                throw new OutputException(shown + ": cannot be written: the folder " + Display.path(dir)
                        + " does not exist (create it first)");
            }
            probeIn = existing;
        }
        if (probeIn == null) {
            throw new OutputException(shown + ": cannot be written: no existing folder on its path");
        }
        Path probe = probeIn.resolve(".raylab-probe." + ProcessHandle.current().pid() + "."
                + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
        try {
            track(probe);
            Files.newOutputStream(probe, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
        } catch (IOException e) {
            throw new OutputException(shown + ": cannot be written: the folder " + Display.path(probeIn)
                    + " " + reason(e));
        } finally {
            untrackAndDelete(probe);
        }
    }

    /** Why a file could not be created, as a phrase after "the folder X". */
    private static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "is not writable (permission denied)";
        }
        if (e instanceof NoSuchFileException) {
            return "does not accept new files";
        }
        String r = e instanceof FileSystemException f && f.getReason() != null ? f.getReason() : e.getMessage();
        return "does not accept a new file (" + Display.escape(String.valueOf(r)) + ")";
    }

    private static BasicFileAttributes attributes(Path p) {
        try {
            return Files.readAttributes(p, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
        } catch (IOException absent) {
            return null;
        }
    }

    /**
     * Writes the picture as a PNG: encoded in memory, written to a temporary file beside
     * {@code target}, renamed over the target. If anything fails, or the JVM is stopped, the
     * target is untouched and the temporary file removed. Missing folders are created.
     */
    public static void write(BufferedImage image, Path target) throws IOException {
        Path abs = target.toAbsolutePath();
        BasicFileAttributes a = attributes(abs);
        if (a != null && !a.isRegularFile()) {
            checkTarget(target, true); // throws with the reason
        }
        ExposedBytes png = new ExposedBytes();
        if (!ImageIO.write(image, "png", png)) {
            throw new IOException("no PNG writer is available");
        }
        Path dir = abs.getParent();
        if (dir != null) {
            Files.createDirectories(dir);
        }
        removeStaleTemporaries(abs);
        // Not Files.createTempFile: that makes the file owner-only (rw-------), and the rename
        // would hand those permissions to the picture. A new file gets the usual ones (umask).
        Path tmp = abs.resolveSibling("." + abs.getFileName() + "." + ProcessHandle.current().pid() + "."
                + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
        try {
            track(tmp);
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
                writeAll(ch, png);
                ch.force(true);
            }
            synchronized (LOCK) {
                if (shuttingDown) {
                    throw new IOException("stopped before " + Display.path(target) + " was written");
                }
                try {
                    Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        } catch (FileSystemException e) {
            // Name the target, not the temporary file, and say why.
            String why = e.getReason() != null ? e.getReason()
                    : e instanceof AccessDeniedException ? "permission denied" : e.getClass().getSimpleName();
            throw new IOException(Display.path(target) + ": cannot be written: " + Display.escape(why), e);
        } finally {
            untrackAndDelete(tmp);
        }
    }

    private static void writeAll(FileChannel ch, ExposedBytes png) throws IOException {
        long pause = Long.getLong(SLOW_WRITE_PROPERTY, 0);
        int chunk = pause > 0 ? 4 << 10 : 1 << 20;
        for (int off = 0; off < png.size(); off += chunk) {
            ByteBuffer b = ByteBuffer.wrap(png.buffer(), off, Math.min(chunk, png.size() - off));
            while (b.hasRemaining()) {
                ch.write(b);
            }
            if (pause > 0) {
                try {
                    Thread.sleep(pause);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IOException("interrupted");
                }
            }
        }
    }

    /** Deletes .NAME.PID.*.tmp beside the target whose process PID no longer runs (after a KILL). */
    private static void removeStaleTemporaries(Path abs) {
        Path dir = abs.getParent();
        if (dir == null) {
            return;
        }
        String name = abs.getFileName().toString();
        Pattern p = Pattern.compile("\\." + Pattern.quote(name) + "\\.(\\d+)\\.[0-9a-z]+\\.tmp");
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, "." + globEscape(name) + ".*.tmp")) {
            for (Path f : s) {
                Matcher m = p.matcher(f.getFileName().toString());
                if (m.matches() && ProcessHandle.of(Long.parseLong(m.group(1))).isEmpty()
                        && Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS)) {
                    Files.deleteIfExists(f);
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // Only housekeeping: never a reason to fail a write.
        }
    }

    private static String globEscape(String s) {
        return s.replaceAll("([\\\\*?\\[\\]{}])", "\\\\$1");
    }

    private static void track(Path tmp) throws IOException {
        synchronized (LOCK) {
            if (shuttingDown) {
                throw new IOException("stopping");
            }
            if (!hookInstalled) {
                Runtime.getRuntime().addShutdownHook(new Thread(PngFiles::onShutdown, "raylab-png-cleanup"));
                hookInstalled = true;
            }
            PENDING.add(tmp);
        }
    }

    private static void untrackAndDelete(Path tmp) {
        try {
            Files.deleteIfExists(tmp); // usually gone already (renamed)
        } catch (IOException | RuntimeException e) {
            // Left for the shutdown hook to try again.
            return;
        }
        synchronized (LOCK) {
            PENDING.remove(tmp);
        }
    }

    private static void onShutdown() {
        synchronized (LOCK) {
            shuttingDown = true;
            for (Path p : PENDING) {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException | RuntimeException ignored) {
                    // Nothing more can be done while the JVM stops.
                }
            }
            PENDING.clear();
        }
    }

    /** A byte buffer whose array can be written without a copy. */
    private static final class ExposedBytes extends ByteArrayOutputStream {
        ExposedBytes() {
            super(1 << 16);
        }

        byte[] buffer() {
            return buf;
        }
    }

    /** Reads a PNG (or any format javax.imageio knows); fails with a clear message otherwise. */
    public static BufferedImage read(Path file) throws IOException {
        if (!Files.exists(file)) {
            throw new IOException(Display.path(file) + ": no such file");
        }
        if (!Files.isRegularFile(file)) {
            throw new IOException(Display.path(file) + ": not a regular file");
        }
        BufferedImage img = ImageIO.read(file.toFile());
        if (img == null) {
            throw new IOException(Display.path(file) + ": not an image that can be read");
        }
        return img;
    }
}
