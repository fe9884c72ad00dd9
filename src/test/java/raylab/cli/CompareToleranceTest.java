package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignment;
import raylab.course.Assignments;

/** {@code render --compare} uses the scene's grading tolerance unless --tolerance says otherwise. */
class CompareToleranceTest {
    @TempDir
    Path dir;

    private static String render(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out), new PrintWriter(err), args);
        assertEquals(0, status, () -> out + "\n" + err);
        return out.toString();
    }

    @Test
    void gradedSceneDefaultsToItsGradingTolerance() throws Exception {
        Assignment triangle = Assignments.load(Path.of("").toAbsolutePath()).byId("triangle").orElseThrow();
        Assignment.GradedScene mesh = triangle.scenes().stream().filter(s -> s.scene().equals("scenes/mesh.json"))
                .findFirst().orElseThrow();
        assertEquals(0.005, mesh.tolerance(), "the mesh is graded with a looser tolerance than the default");
        String out = render("render", mesh.scene(), "-o", dir.resolve("m.png").toString(), "--quiet", "--compare",
                mesh.reference());
        assertTrue(out.contains("tolerance: 0.500% (the grading tolerance of scenes/mesh.json)"), out);
        out = render("render", mesh.scene(), "-o", dir.resolve("m2.png").toString(), "--quiet", "--compare",
                mesh.reference(), "--tolerance", "0.01");
        assertTrue(out.contains("tolerance: 1.000%\n") || out.contains("tolerance: 1.000%" + System.lineSeparator()), out);
        // A scene no milestone grades keeps the command's default.
        Path copy = dir.resolve("mine.json");
        Files.copy(Path.of("scenes/sphere.json"), copy);
        out = render("render", copy.toString(), "-o", dir.resolve("s.png").toString(), "--quiet", "--compare",
                "scenes/reference/sphere.png");
        assertTrue(out.contains("tolerance: 0.100%"), out);
    }
}
