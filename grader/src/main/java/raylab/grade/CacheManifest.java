package raylab.grade;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Stream;

import raylab.course.JavaBuild;

/**
 * The grader cache's hash manifest: {@code manifest.sha256} at the top of a cache folder, one
 * line {@code <sha-256>  <path>} per regular file (the format of {@code sha256sum}, so
 * {@code sha256sum -c manifest.sha256} checks it too), sorted by path. {@link #write} is called
 * on a freshly built cache before it is moved into place; {@link #verify} before each grading: a
 * file changed, added, missing or replaced by a link, or no manifest at all, and the cache is not
 * used but rebuilt ({@link #usable}). Where student code runs as the grader's own user (mode
 * none) it could rewrite the manifest as well: {@link Guard} keeps the manifest read at the start
 * of a grading in memory and checks the cache against it once every child is gone, and deletes a
 * cache that changed, so that no later grading uses it.
 */
final class CacheManifest {
    static final String FILE = "manifest.sha256";

    private CacheManifest() {
    }

    /** Writes the manifest of {@code dir} (every regular file but the manifest). */
    static void write(Path dir) throws IOException {
        StringBuilder out = new StringBuilder();
        for (Map.Entry<String, String> e : hashes(dir).entrySet()) {
            out.append(e.getValue()).append("  ").append(e.getKey()).append('\n');
        }
        Files.writeString(dir.resolve(FILE), out, StandardCharsets.UTF_8);
    }

    /** What is wrong with the cache in {@code dir}, or empty when it is exactly what its manifest lists. */
    static Optional<String> verify(Path dir) {
        Path m = dir.resolve(FILE);
        if (!Files.isRegularFile(m, LinkOption.NOFOLLOW_LINKS)) {
            return Optional.of("no " + FILE);
        }
        try {
            return compare(parse(Files.readString(m, StandardCharsets.UTF_8)), hashes(dir));
        } catch (IOException | RuntimeException e) {
            return Optional.of("unreadable: " + e.getMessage());
        }
    }

    /**
     * Whether the cache in {@code dir} may be used: it exists and verifies. A cache that does
     * not verify is deleted (logged with the reason), so that the caller builds it anew.
     */
    static boolean usable(Path dir, java.util.function.Consumer<String> log) {
        if (!Files.isDirectory(dir, LinkOption.NOFOLLOW_LINKS)) {
            if (Files.exists(dir, LinkOption.NOFOLLOW_LINKS)) {
                JavaBuild.deleteTreeQuietly(dir);
            }
            return false;
        }
        Optional<String> problem = verify(dir);
        if (problem.isEmpty()) {
            return true;
        }
        log.accept("grader: the cache " + dir + " does not match its manifest (" + problem.get()
                + "): it is deleted and built again");
        discard(dir);
        return false;
    }

    /** Moves a bad cache aside (so that a grading using it at this moment keeps its files) and deletes it. */
    private static void discard(Path dir) {
        Path aside = dir.resolveSibling(dir.getFileName() + ".bad-" + System.nanoTime());
        try {
            Files.move(dir, aside);
        } catch (IOException e) {
            aside = dir;
        }
        JavaBuild.deleteTreeQuietly(aside);
    }

    /** The cache as one grading found it, to be checked when the grading ends. */
    static Guard guard(Path dir) throws IOException {
        Path m = dir.resolve(FILE);
        Map<String, String> start = parse(Files.readString(m, StandardCharsets.UTF_8));
        start.put(FILE, sha256(m));
        return new Guard(dir, start);
    }

    /** See {@link CacheManifest}: the manifest held in memory from the start of a grading. */
    static final class Guard {
        private final Path dir;
        private final Map<String, String> atStart;

        private Guard(Path dir, Map<String, String> atStart) {
            this.dir = dir;
            this.atStart = atStart;
        }

        /**
         * Checks the cache against the manifest of the start (the manifest file itself
         * included); if anything changed, deletes the cache and says what changed.
         */
        Optional<String> check() {
            Optional<String> problem;
            try {
                Map<String, String> now = hashes(dir);
                now.put(FILE, sha256(dir.resolve(FILE)));
                problem = compare(atStart, now);
            } catch (IOException | RuntimeException e) {
                problem = Optional.of("unreadable: " + e.getMessage());
            }
            if (problem.isPresent()) {
                discard(dir);
                return Optional.of("the grader cache was changed while this submission was graded (" + problem.get()
                        + "): it is deleted, the next grading builds it again");
            }
            return Optional.empty();
        }
    }

    private static Optional<String> compare(Map<String, String> expected, Map<String, String> actual) {
        for (Map.Entry<String, String> e : expected.entrySet()) {
            String got = actual.get(e.getKey());
            if (got == null) {
                return Optional.of(e.getKey() + " is missing");
            }
            if (!got.equals(e.getValue())) {
                return Optional.of(e.getKey() + " was changed (sha-256 " + got.substring(0, 12) + "…, expected "
                        + e.getValue().substring(0, 12) + "…)");
            }
        }
        for (String k : actual.keySet()) {
            if (!expected.containsKey(k)) {
                return Optional.of(k + " is not in the manifest");
            }
        }
        return Optional.empty();
    }

    private static Map<String, String> parse(String text) {
        Map<String, String> out = new TreeMap<>();
        for (String line : text.split("\n")) {
            if (line.isEmpty()) {
                continue;
            }
            int k = line.indexOf("  ");
            if (k != 64) {
                throw new IllegalArgumentException("malformed line: " + line);
            }
            out.put(line.substring(66), line.substring(0, 64));
        }
        return out;
    }

    /** Every regular file under {@code dir} but the manifest, by relative path; a link or special file is an error. */
    private static Map<String, String> hashes(Path dir) throws IOException {
        Map<String, String> out = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String rel = dir.relativize(p).toString().replace('\\', '/');
                if (Files.isSymbolicLink(p)) {
                    throw new IOException(rel + " is a symbolic link");
                }
                if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                    throw new IOException(rel + " is not a regular file");
                }
                if (!rel.equals(FILE)) {
                    out.put(rel, sha256(p));
                }
            }
        }
        return out;
    }

    private static String sha256(Path p) throws IOException {
        MessageDigest md = digest();
        try (InputStream in = Files.newInputStream(p, LinkOption.NOFOLLOW_LINKS)) {
            byte[] buf = new byte[1 << 16];
            for (int n; (n = in.read(buf)) > 0;) {
                md.update(buf, 0, n);
            }
        }
        return HexFormat.of().formatHex(md.digest());
    }

    private static MessageDigest digest() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
