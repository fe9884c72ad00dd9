import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Stream;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;

/**
 * Writes a bundled submission as GraderTest builds it: the reference student files, flat,
 * overlaid with src/test/resources/submissions/NAME ("reference": no overlay).
 * Usage: java -cp target/raylab.jar src/bench/boundary/MakeSubmission.java ROOT NAME OUTDIR
 */
public class MakeSubmission {
    public static void main(String[] args) throws Exception {
        Path root = Path.of(args[0]).toAbsolutePath();
        String overlay = args[1];
        Path sub = Path.of(args[2]);
        Files.createDirectories(sub);
        for (Assignment a : Assignments.load(root).all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                Files.writeString(sub.resolve(src.getFileName()),
                        SolutionRegions.toStudent(src.getFileName().toString(), Files.readString(src), Set.of(a.id())));
            }
        }
        if (!overlay.equals("reference")) {
            Path from = root.resolve("src/test/resources/submissions").resolve(overlay);
            try (Stream<Path> s = Files.walk(from)) {
                for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile)::iterator) {
                    Path t = sub.resolve(from.relativize(p).toString());
                    Files.createDirectories(t.getParent());
                    Files.writeString(t, Files.readString(p).replace("@OUT@", sub.resolveSibling(overlay + "-out").toString()));
                }
            }
        }
    }
}
