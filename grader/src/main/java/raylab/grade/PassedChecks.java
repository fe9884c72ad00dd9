package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;

/**
 * The course self-checks that {@code bundle} saw pass, so that bundling the same files again (for
 * another platform, or after a failed upload) does not run the same minutes-long check again. A
 * record is a file under {@link #FOLDER} of the instructor's project, named by a digest of
 * everything the check's outcome depends on: the files the bundle holds (each one's path under the
 * root and its bytes), raylab's own classes and the JDK that ran the check. A change to any of
 * them is a new name, so the check runs again; the record's text is when it passed. Only passes
 * are recorded. {@code raylab self-check} (what Gradescope's setup.sh runs in the image) always
 * checks.
 */
final class PassedChecks {
    /** Where the records are, under the project root. */
    static final String FOLDER = "target/bundle-checks";

    private PassedChecks() {
    }

    /** The record of a passed check of {@code files} (under {@code root}) with this raylab and this JDK. */
    static Path record(Path root, List<Path> files) throws IOException {
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
        md.update(("raylab " + GraderSetup.digestOf(GraderSetup.codeSource()) + "\njava " + System.getProperty("java.home")
                + " " + System.getProperty("java.vm.version") + "\n").getBytes(StandardCharsets.UTF_8));
        for (Path f : files.stream().sorted().toList()) {
            byte[] bytes = Files.readAllBytes(f);
            md.update((root.relativize(f).toString().replace('\\', '/') + "\n" + bytes.length + "\n")
                    .getBytes(StandardCharsets.UTF_8));
            md.update(bytes);
        }
        return root.resolve(FOLDER).resolve(HexFormat.of().formatHex(md.digest()).substring(0, 24) + ".passed");
    }

    /** When the check recorded in {@code record} passed; empty when it did not (or no record can be read). */
    static Optional<String> passedOn(Path record) {
        try {
            String when = Files.readString(record, StandardCharsets.UTF_8).strip();
            return when.isEmpty() ? Optional.empty() : Optional.of(when);
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /** Records a pass (now), whole or not at all: written beside it, then moved into place. */
    static void remember(Path record) throws IOException {
        Files.createDirectories(record.getParent());
        Path tmp = Files.createTempFile(record.getParent(), ".check", ".tmp");
        try {
            Files.writeString(tmp, Instant.now().toString() + "\n", StandardCharsets.UTF_8);
            Files.move(tmp, record, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
