package raylab.course;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/**
 * Folder trees for tests that set up a project, a submission or a bundle on disk: the test-side
 * partner of {@link JavaBuild#deleteTree}.
 */
public final class FileTrees {
    private FileTrees() {
    }

    /**
     * Copies a folder and everything in it to {@code to} (created; files already there are not
     * replaced), each file with {@code options} ({@code COPY_ATTRIBUTES} keeps its time, as a
     * platform's copies of the same course files do).
     */
    public static void copy(Path from, Path to, java.nio.file.CopyOption... options) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                Path t = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(t);
                } else {
                    Files.copy(p, t, options);
                }
            }
        }
    }
}
