package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/** The render command's contract: exit statuses, one-line errors, no partial output files. */
class RenderCommandTest {
    static final Path CORPUS = Path.of("src", "test", "resources", "malformed");

    @TempDir
    Path dir;

    record Run(int status, String out, String err) {
    }

    static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    @TestFactory
    Stream<DynamicTest> everyMalformedSceneExitsWithStatus2AndOneLineAndNoImage() throws IOException {
        List<String> lines = Files.readAllLines(CORPUS.resolve("expected.tsv"), StandardCharsets.UTF_8);
        List<DynamicTest> tests = new ArrayList<>();
        for (String line : lines) {
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            String name = line.substring(0, line.indexOf('\t'));
            String expected = line.substring(line.indexOf('\t') + 1);
            tests.add(DynamicTest.dynamicTest(name, () -> {
                Path png = dir.resolve(name + ".png");
                Run r = run("render", CORPUS.resolve(name).toString(), "-o", png.toString());
                assertEquals(2, r.status(), () -> name + ": exit status; stderr was: " + r.err());
                String err = r.err().strip();
                assertFalse(err.contains("\n"), () -> name + ": error is not one line: " + err);
                assertEquals("raylab: " + expected, err.replace(CORPUS + "/", ""), name + ": error line");
                assertFalse(Files.exists(png), () -> name + ": an image was written despite the error");
                try (Stream<Path> left = Files.list(dir)) {
                    assertEquals(0, left.count(), () -> name + ": files were left in the output folder");
                }
            }));
        }
        assertTrue(tests.size() >= 30, "the corpus has at least 30 cases, found " + tests.size());
        return tests.stream();
    }

    @Test
    void rendersAndPrintsThePlanAndCounters() {
        Path png = dir.resolve("sphere.png");
        Run r = run("render", "scenes/sphere.json", "-o", png.toString(), "--threads", "2");
        assertEquals(0, r.status(), () -> "stderr: " + r.err());
        assertTrue(Files.isRegularFile(png), "image written to " + png);
        for (String word : List.of("plan:", "lighting", "acceleration", "eye rays", "shadow rays",
                "intersection tests", "time: load")) {
            assertTrue(r.out().contains(word), () -> "output should mention '" + word + "':\n" + r.out());
        }
        assertTrue(r.out().contains("76,800"), () -> "320x240 pixels = 76,800 eye rays:\n" + r.out());
    }

    @Test
    void badOptionsAreOneLineWithStatus2() {
        Run r = run("render", "scenes/sphere.json", "--threads", "0", "-o", dir.resolve("x.png").toString());
        assertEquals(2, r.status(), r.err());
        assertEquals("raylab: --threads must be at least 1, got 0", r.err().strip());
        Run unknown = run("render", "scenes/sphere.json", "--frobnicate");
        assertEquals(2, unknown.status(), unknown.err());
        assertEquals(1, unknown.err().strip().lines().count(), () -> "one line: " + unknown.err());
        Run missing = run("render", dir.resolve("nope.json").toString());
        assertEquals(2, missing.status(), missing.err());
        assertEquals(1, missing.err().strip().lines().count(), () -> "one line: " + missing.err());
    }

    @Test
    void compareReportsTheMetricWritesTheHeatmapAndFailsOnMismatch() throws IOException {
        Path a = dir.resolve("a.png");
        assertEquals(0, run("render", "scenes/sphere.json", "-o", a.toString()).status());
        Run same = run("render", "scenes/sphere.json", "-o", dir.resolve("b.png").toString(), "--compare", a.toString());
        assertEquals(0, same.status(), same.out() + same.err());
        assertTrue(same.out().contains("MATCH") && same.out().contains("rmse 0.000/255"), same.out());
        assertTrue(Files.isRegularFile(dir.resolve("b.diff.png")), "heatmap next to the output");
        Path other = dir.resolve("other.png");
        assertEquals(0, run("render", "scenes/sphere.json", "--mode", "normals", "-o", other.toString()).status());
        Run diff = run("render", "scenes/sphere.json", "-o", dir.resolve("c.png").toString(), "--compare",
                other.toString());
        assertEquals(1, diff.status(), diff.out() + diff.err());
        assertTrue(diff.out().contains("DIFFERS"), diff.out());
    }

    @Test
    void traceShowsTheRayTreeOfALitAndAShadowedPixel() {
        Run lit = run("trace", "scenes/shadows.json", "--pixel", "150", "130");
        assertEquals(0, lit.status(), lit.err());
        assertTrue(lit.out().contains("hit \"clay ball\""), lit.out());
        assertTrue(lit.out().contains("diffuse"), lit.out());
        Run shadowed = run("trace", "scenes/shadows.json", "--pixel", "215", "195");
        assertEquals(0, shadowed.status(), shadowed.err());
        assertTrue(shadowed.out().contains("BLOCKED by"), shadowed.out());
        Run outside = run("trace", "scenes/shadows.json", "--pixel", "400", "0");
        assertEquals(2, outside.status(), outside.err());
    }

    @Test
    void traceOnTheShowcaseExplainsAShadowedAndALitPixel() {
        Run shadowed = run("trace", "scenes/showcase.json", "--pixel", "1050", "600");
        assertEquals(0, shadowed.status(), shadowed.err());
        assertTrue(shadowed.out().contains("hit \"floor\""), shadowed.out());
        assertTrue(shadowed.out().contains("BLOCKED by \"blue ball\""), shadowed.out());
        assertTrue(shadowed.out().contains("colour L ="), shadowed.out());
        Run lit = run("trace", "scenes/showcase.json", "--pixel", "330", "420");
        assertEquals(0, lit.status(), lit.err());
        assertTrue(lit.out().contains("hit \"gold ball\""), lit.out());
        assertFalse(lit.out().contains("BLOCKED"), lit.out());
        assertTrue(lit.out().contains("specular ks*I*max(0, n.h)^p"), lit.out());
    }
}
