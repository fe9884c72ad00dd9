package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;

/**
 * The autograder end to end, through {@code raylab grade}: the reference solution scores 100%,
 * the untouched release scores 0 with a TODO in every message, alternative correct methods
 * earn full marks, realistic single bugs lose points in their milestone only, and hostile
 * submissions cannot break grading. Submissions are the reference files overlaid with the
 * files in src/test/resources/submissions/NAME. Limits are kept small so the suite is quick.
 * The project root is the working directory, or the system property raylab.grade.root.
 */
@ExtendWith(SharedGraderCache.class)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class GraderTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path root;
    static Assignments assignments;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        assignments = Assignments.load(root);
    }

    /** The reference student files, flat, overlaid with a resource submission. */
    private Path submission(String overlay) throws IOException {
        return submission(dir, overlay);
    }

    /** As above, in {@code dir} (shared with {@link RealisticBugsTest}). */
    static Path submission(Path dir, String overlay) throws IOException {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path sub = dir.resolve("submission-" + overlay);
        Files.createDirectories(sub);
        for (Assignment a : Assignments.load(root).all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                String text = SolutionRegions.toStudent(src.getFileName().toString(), Files.readString(src),
                        Set.of(a.id()));
                Files.writeString(sub.resolve(src.getFileName()), text);
            }
        }
        if (!overlay.equals("reference")) {
            Path res = Path.of("src/test/resources/submissions", overlay);
            if (!Files.isDirectory(res)) {
                res = root.resolve("src/test/resources/submissions").resolve(overlay);
            }
            Path from = res;
            try (Stream<Path> s = Files.walk(from)) {
                for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile)::iterator) {
                    Path t = sub.resolve(from.relativize(p).toString());
                    Files.createDirectories(t.getParent());
                    Files.writeString(t, Files.readString(p).replace("@OUT@", dir.resolve("out").toString()));
                }
            }
        }
        return sub;
    }

    /** Runs raylab grade with small limits and returns results.json. */
    private JsonNode grade(Path sub, String... extra) throws IOException {
        return grade(sub, 40, 25, extra);
    }

    /** As above, with the given time limits (seconds) of a milestone's tests and of one scene render. */
    private JsonNode grade(Path sub, int milestoneSeconds, int sceneSeconds, String... extra) throws IOException {
        return grade(sub, 2, milestoneSeconds, sceneSeconds, extra);
    }

    /** As above, with the given time limit (seconds of the student's CPU time) of one test too. */
    private JsonNode grade(Path sub, int testSeconds, int milestoneSeconds, int sceneSeconds, String... extra)
            throws IOException {
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        String[] base = {"grade", sub.toString(), "--out", out.toString(), "--root", root.toString(), "--quiet",
            "--test-timeout", Integer.toString(testSeconds), "--milestone-timeout", Integer.toString(milestoneSeconds),
            "--scene-timeout", Integer.toString(sceneSeconds),
            "--heap", "256", "--sandbox-user", sandboxUser(),
            // The graded scenes' variants of one fixed seed: a failure is reproduced by the same run.
            "--seed", "17"};
        String[] args = new String[base.length + extra.length];
        System.arraycopy(base, 0, args, 0, base.length);
        System.arraycopy(extra, 0, args, base.length, extra.length);
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args);
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8));
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        checkSchema(r);
        for (String f : Reports.FILES) {
            assertTrue(Files.isRegularFile(out.resolve(f)), f + " written");
        }
        return r;
    }

    /**
     * The sandbox user (system property raylab.grade.sandboxUser, default raylab-student): another
     * user keeps these tests apart from other gradings on the same machine.
     */
    static String sandboxUser() {
        return System.getProperty("raylab.grade.sandboxUser", Sandbox.DEFAULT_USER);
    }

    /** The Gradescope fields, and a score that is the sum of the tests' scores. */
    static void checkSchema(JsonNode r) {
        assertTrue(r.get("score").isNumber(), "score");
        assertTrue(r.get("execution_time").isNumber(), "execution_time");
        assertTrue(r.get("output").isTextual(), "output");
        double sum = 0;
        for (JsonNode t : r.get("tests")) {
            for (String f : List.of("name", "number", "output", "status", "visibility")) {
                assertTrue(t.get(f).isTextual(), f + " of " + t);
            }
            assertTrue(t.get("score").isNumber() && t.get("max_score").isNumber(), "scores of " + t);
            assertTrue(t.get("tags").isArray(), "tags of " + t);
            assertTrue(Set.of("passed", "failed").contains(t.get("status").asText()), "status of " + t);
            assertTrue(Set.of("visible", "hidden", "after_due_date", "after_published").contains(t.get("visibility").asText()));
            sum += t.get("score").asDouble();
        }
        assertEquals(sum, r.get("score").asDouble(), 1e-3, "score is the sum of the tests");
    }

    /** Score and maximum per milestone. */
    static Map<String, double[]> perMilestone(JsonNode r) {
        Map<String, double[]> m = new HashMap<>();
        for (JsonNode t : r.get("tests")) {
            double[] s = m.computeIfAbsent(t.get("tags").get(0).asText(), k -> new double[2]);
            s[0] += t.get("score").asDouble();
            s[1] += t.get("max_score").asDouble();
        }
        return m;
    }

    private static void assertFull(Map<String, double[]> m, String... ids) {
        for (String id : ids) {
            assertEquals(m.get(id)[1], m.get(id)[0], 1e-6, id + " should have full marks");
        }
    }

    private static void assertZero(JsonNode r, Map<String, double[]> m, String... ids) {
        for (String id : ids) {
            assertEquals(0, m.get(id)[0], 1e-6, id + " should score 0");
            for (JsonNode t : r.get("tests")) {
                if (t.get("tags").get(0).asText().equals(id)) {
                    assertFalse(t.get("output").asText().isBlank(), "every lost point is explained: " + t);
                }
            }
        }
    }

    private static void assertLoses(Map<String, double[]> m, String id) {
        assertTrue(m.get(id)[0] < m.get(id)[1] - 1e-6, id + " should lose points: " + m.get(id)[0] + "/" + m.get(id)[1]);
    }

    @Test
    @Order(1)
    void referenceSolutionScoresFullMarks() throws IOException {
        JsonNode r = grade(submission("reference"));
        assertEquals(100.0 * 1, 100 * r.get("score").asDouble() / perMilestone(r).values().stream()
                .mapToDouble(v -> v[1]).sum(), 1e-6, () -> "reference: " + r.get("output").asText());
    }

    @Test
    @Order(2)
    void untouchedReleaseScoresZeroAndNamesTheTodo() throws IOException {
        Path sub = dir.resolve("release");
        Files.createDirectories(sub.resolve("src/main/java"));
        for (Assignment a : assignments.all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                Path t = sub.resolve(f.path());
                Files.createDirectories(t.getParent());
                Files.writeString(t, SolutionRegions.toStudent(src.getFileName().toString(), Files.readString(src), Set.of()));
            }
        }
        JsonNode r = grade(sub);
        assertEquals(0, r.get("score").asDouble(), 1e-9);
        for (JsonNode t : r.get("tests")) {
            String why = t.get("output").asText();
            assertTrue(why.contains("not implemented yet: write "), "says which TODO to write: " + t);
        }
    }

    @Test
    @Order(3)
    void alternativeCorrectMethodsEarnFullMarksAndBugsLosePointsInTheirMilestoneOnly() throws IOException {
        // Geometric sphere, Möller–Trumbore, unit-direction shadow rays, explicit Lambert, an
        // index loop over the lights summing channels by hand;
        // a box with swapped slabs missing, a half vector not normalized.
        Path sub = submission("alternatives");
        for (Path p : List.of(Path.of("src/test/resources/submissions/bugs1"))) {
            try (Stream<Path> s = Files.list(p)) {
                for (Path f : (Iterable<Path>) s::iterator) {
                    Files.copy(f, sub.resolve(f.getFileName()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        Map<String, double[]> m = perMilestone(grade(sub));
        assertFull(m, "sphere", "triangle", "lambert", "shadows");
        assertLoses(m, "box");
        assertLoses(m, "phong");
    }

    @Test
    @Order(4)
    void moreAlternativesAndMoreBugs() throws IOException {
        // Inverse-direction box, explicit half vector; near root only, record overwritten,
        // shadow ray without offset, the ambient term once per light.
        Path sub = submission("alternatives2");
        try (Stream<Path> s = Files.list(Path.of("src/test/resources/submissions/bugs2"))) {
            for (Path f : (Iterable<Path>) s::iterator) {
                Files.copy(f, sub.resolve(f.getFileName()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        }
        Map<String, double[]> m = perMilestone(grade(sub));
        assertFull(m, "box", "phong");
        assertLoses(m, "lambert");
        assertLoses(m, "sphere");
        assertLoses(m, "triangle");
        assertLoses(m, "shadows");
    }

    @Test
    @Order(5)
    void hostileSubmissionsExitFakeResultsWriteFilesAndFlood() throws IOException {
        Path sub = submission("hostile1");
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        JsonNode r = grade(sub, "--milestone", "sphere", "--milestone", "box", "--milestone", "lambert",
                "--milestone", "phong");
        Map<String, double[]> m = perMilestone(r);
        assertZero(r, m, "sphere", "phong");
        // The hostile Lambertian writes fake results to fd 1 and files, then throws. The protocol has a
        // channel of its own (issue 35), so its writes break nothing: every test that calls its diffuse
        // fails with its own exception, and the reference Shading beside it keeps the points of the
        // tests that never call diffuse (no lights, a light behind the surface or at the point).
        assertLoses(m, "lambert");
        for (JsonNode t : r.get("tests")) {
            if (t.get("tags").get(0).asText().equals("lambert") && t.get("score").asDouble() < t.get("max_score").asDouble()) {
                assertTrue(t.get("output").asText().contains("IllegalStateException in Lambertian.diffuse"),
                        "a lost lambert point is the Lambertian's own exception: " + t);
            }
        }
        assertFull(m, "box");
        assertTrue(r.get("score").asDouble() < 1000, "the fake results were not taken");
        assertFalse(Files.exists(out.resolve("evil.txt")), "files written into the results directory are removed");
        // Students see one line about ignored files; the instructors' report lists them.
        String output = r.get("output").asText();
        assertTrue(output.contains("submitted files were not graded") && !output.contains("raylab/math/Vec3.java"), output);
        String report = Files.readString(out.resolve("report.html"));
        assertTrue(report.contains("raylab/math/Vec3.java"), "the framework file is listed as ignored: " + report);
        assertTrue(report.contains("src/test/java/raylab/surface/SphereTest.java"), "the test file is ignored: " + report);
        assertTrue(Files.size(out.resolve("results.json")) < 2_000_000, "output is capped");
    }

    @Test
    @Order(6)
    void hostileSubmissionsLoopExhaustMemoryRecurseAndLeaveThreads() throws IOException {
        // The endless loops run until their time limits, so these are short: 1 s of the student's
        // CPU time a test (each of a group's four stops before its process is given up burns
        // that much; the reference's lambert tests take milliseconds), 15 s for a milestone's tests
        // and 8 s a scene (the whole of lambert, tests and renders, takes about 4 s here).
        JsonNode r = grade(submission("hostile2"), 1, 15, 8, "--milestone", "sphere", "--milestone", "box",
                "--milestone", "triangle", "--milestone", "lambert");
        Map<String, double[]> m = perMilestone(r);
        assertZero(r, m, "sphere", "box", "triangle");
        assertFull(m, "lambert");
        assertTrue(r.get("output").asText().contains("raylab.surface.Bvh"), "the shadowing class is reported: "
                + r.get("output").asText());
    }

    @Test
    @Order(7)
    void anUnreadableSubmissionStillGivesAValidResultsFile() throws IOException {
        Path bad = dir.resolve("broken.zip");
        Files.writeString(bad, "not a zip");
        JsonNode r = grade(bad, "--milestone", "lambert");
        assertEquals(0, r.get("score").asDouble(), 1e-9);
        assertTrue(r.get("output").asText().contains("not a readable zip"), r.get("output").asText());
    }

    @Test
    @Order(8)
    void aCompileErrorZeroesOnlyItsMilestoneAndNamesFileAndLine() throws IOException {
        Path sub = submission("reference");
        Files.writeString(sub.resolve("Lambertian.java"), Files.readString(sub.resolve("Lambertian.java"))
                .replace("public Color diffuse(Vec3 n, Vec3 l, Color I) {", "public Color diffuse(Vec3 n, Vec3 l, Color I) { int x = ;"));
        JsonNode r = grade(sub, "--milestone", "lambert", "--milestone", "phong");
        Map<String, double[]> m = perMilestone(r);
        assertZero(r, m, "lambert");
        assertFull(m, "phong");
        String why = r.get("tests").get(0).get("output").asText();
        assertTrue(why.contains("src/main/java/raylab/material/Lambertian.java:"), why);
    }

    static String read(InputStream in) throws IOException {
        return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    }

    static Duration unused() {
        return Duration.ZERO;
    }
}
