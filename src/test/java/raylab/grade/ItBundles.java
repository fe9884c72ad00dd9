package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.util.HexFormat;

import raylab.cli.Main;
import raylab.course.Assignments;

/**
 * The PrairieLearn bundle the integration tests grade with, built once per run and shared: a
 * build is the course's self-check (a whole grading of the reference with a new cache; the other
 * platforms' bundles of the same files find it passed, {@link PassedChecks}) and the bundle, and
 * {@code PlatformBundlesIT} and both cases of {@code PrairieLearnJobFolderIT} bundled the same
 * files with the same jar three times. Built under {@code target/it-bundles/}, named by a digest
 * of the jar and of every file the bundle takes ({@link BundleCommand#graderFiles}), under a file
 * lock (the two failsafe JVMs may ask at once); the bundle command writes into a temporary
 * folder and moves it into place, so a folder that exists is whole. Tests only read it.
 */
final class ItBundles {
    private ItBundles() {
    }

    /** The folder {@code raylab bundle prairielearn --root ROOT --jar JAR} writes (questions/, serverFilesCourse/). */
    static Path prairieLearn(Path root, Path jar) throws Exception {
        assertTrue(Files.isRegularFile(jar), "needs target/raylab.jar: run with ./mvnw verify, which packages it first");
        Path shared = Files.createDirectories(Path.of("target/it-bundles").toAbsolutePath());
        Path out = shared.resolve("prairielearn-" + digest(root, jar));
        try (FileChannel ch = FileChannel.open(shared.resolve(".lock"), StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                FileLock lock = ch.lock()) {
            if (!Files.isDirectory(out)) {
                ByteArrayOutputStream err = new ByteArrayOutputStream();
                assertEquals(0, Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(err, true),
                        "bundle", "prairielearn", "--out", out.toString(), "--root", root.toString(), "--jar", jar.toString()),
                        () -> "bundle: " + err);
            }
        }
        return out;
    }

    /** SHA-256 of the jar and of each file the bundle takes (its path under the root and its bytes). */
    private static String digest(Path root, Path jar) throws IOException {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            md.update(root.toString().getBytes(StandardCharsets.UTF_8));
            md.update(Files.readAllBytes(jar));
            for (Path f : BundleCommand.graderFiles(root, Assignments.load(root))) {
                md.update(root.relativize(f).toString().getBytes(StandardCharsets.UTF_8));
                md.update(Files.readAllBytes(f));
            }
            return HexFormat.of().formatHex(md.digest()).substring(0, 20);
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
