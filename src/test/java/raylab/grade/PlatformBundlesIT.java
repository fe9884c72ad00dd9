package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;
import raylab.course.SolutionRegions;
import raylab.course.release.Release;
import raylab.grade.platform.PlatformSchemas;

/**
 * The PrairieLearn and Classroom 50 bundles end to end, without Docker or GitHub: the
 * PrairieLearn entrypoint runs in a folder laid out like the grading container's /grade, and
 * Classroom 50's autograder.py runs with the runner's documented environment in a git checkout
 * of the starter with a submission in it. Each grades the reference (full marks) and a buggy box
 * (points lost in the box milestone, scene images attached); the results are validated against
 * the schemas written from the platforms' documentation. Runs after `package` (target/raylab.jar).
 */
class PlatformBundlesIT {
    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    static Path root() {
        return Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    }

    static String reference(Path root, String milestone, String file) throws Exception {
        Assignment a = Assignments.load(root).byId(milestone).orElseThrow();
        for (Assignment.StudentFile f : a.files()) {
            Path src = root.resolve(f.path());
            if (src.getFileName().toString().equals(file)) {
                return SolutionRegions.toStudent(file, Files.readString(src), Set.of(milestone));
            }
        }
        throw new AssertionError("no " + file + " in " + milestone);
    }

    static int run(Path cwd, Map<String, String> env, Path log, String... cmd) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        pb.environment().putAll(env);
        Process p = pb.start();
        assertTrue(p.waitFor(900, TimeUnit.SECONDS), () -> String.join(" ", cmd) + " finished");
        return p.exitValue();
    }

    @Test
    void prairieLearnEntrypointGradesAGradeFolder() throws Exception {
        Path root = root();
        Files.setPosixFilePermissions(dir, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        // Built once for all the integration tests (ItBundles: the bundle command's self-check is a grading).
        Path course = ItBundles.prairieLearn(root, Path.of("target/raylab.jar").toAbsolutePath());
        // One question per milestone, each uploading exactly its files.
        for (Assignment a : Assignments.load(root).all()) {
            Path q = course.resolve("questions/raylab").resolve(a.id());
            JsonNode info = JSON.readTree(q.resolve("info.json").toFile());
            JsonNode ext = info.get("externalGradingOptions");
            assertEquals("External", info.get("gradingMethod").asText());
            assertTrue(ext.get("enabled").asBoolean());
            assertEquals("prairielearn/grader-java", ext.get("image").asText());
            assertEquals("[\"raylab/\"]", ext.get("serverFilesCourse").toString());
            assertEquals("/grade/serverFilesCourse/raylab/grade.sh " + a.id(), ext.get("entrypoint").asText());
            assertTrue(ext.get("timeout").asInt() <= 600, "PrairieLearn's limit: " + ext);
            assertFalse(ext.get("enableNetworking").asBoolean());
            List<String> names = a.files().stream().map(f -> f.path().substring(f.path().lastIndexOf('/') + 1)).toList();
            String html = Files.readString(q.resolve("question.html"));
            assertTrue(html.contains("<pl-file-upload file-names=\"" + String.join(", ", names) + "\">"), html);
            assertTrue(html.contains("<pl-external-grader-results>"), html);
        }
        Path sfc = course.resolve("serverFilesCourse/raylab");
        for (String f : List.of("grade.sh", "raylab.jar", "assignments/02-box/assignment.json",
                "grader/tests/raylab/surface/BoxHiddenTest.java", "scenes/reference/boxes.png")) {
            assertTrue(Files.isRegularFile(sfc.resolve(f)), "serverFilesCourse has " + f);
        }
        JsonNode box = JSON.readTree(course.resolve("questions/raylab/box/info.json").toFile());
        String[] entry = box.get("externalGradingOptions").get("entrypoint").asText().split(" ");

        // The reference box, on time (no due date in this bundle): full marks of every point, the
        // hidden tests and data cases graded and counted, shown as one row with their total only.
        Assignment boxA = Assignments.load(root).byId("box").orElseThrow();
        JsonNode ref = gradePrairieLearn(sfc, entry, "Box.java", reference(root, "box", "Box.java"), "reference");
        assertTrue(ref.get("gradable").asBoolean());
        assertEquals(1.0, ref.get("score").asDouble(), 1e-9, () -> "reference box: " + ref.get("message") + ref.get("tests"));
        assertTrue(ref.get("tests").size() > 5, "per-test entries: " + ref.get("tests"));
        double max = 0;
        JsonNode hiddenRow = null;
        for (JsonNode t : ref.get("tests")) {
            assertFalse(t.get("name").asText().contains("Hidden"), "no hidden test's name before the due date: " + t);
            assertTrue(t.get("name").asText().startsWith("box: "), t.toString());
            max += t.get("max_points").asDouble();
            if (t.get("name").asText().equals("box: " + raylab.grade.platform.PrairieLearn.HIDDEN_ROW)) {
                hiddenRow = t;
            }
        }
        assertEquals(boxA.points(), max, 1e-6, "the grade of record is of all the milestone's points: " + ref.get("tests"));
        assertTrue(hiddenRow != null && hiddenRow.get("max_points").asDouble() >= boxA.tests().hiddenPoints(),
                "the hidden tests counted, as one total: " + ref.get("tests"));
        assertEquals(hiddenRow.get("max_points").asDouble(), hiddenRow.get("points").asDouble(), 1e-9, hiddenRow.toString());

        // The lecture's slabs as written (no case for d = 0): points lost, the scene that shows it with its images.
        String buggy = Files.readString(root.resolve("src/test/resources/submissions/bugs3/Box.java"));
        JsonNode bug = gradePrairieLearn(sfc, entry, "Box.java", buggy, "bugs3");
        assertTrue(bug.get("gradable").asBoolean());
        assertTrue(bug.get("score").asDouble() < 1 && bug.get("score").asDouble() > 0.5, () -> "bugs3 box: " + bug.get("score"));
        JsonNode front = null;
        for (JsonNode t : bug.get("tests")) {
            if (t.get("name").asText().equals("box: scenes/boxes-front.json")) {
                front = t;
            }
        }
        assertTrue(front != null, "the scene boxes-front.json graded: " + bug.get("tests"));
        assertEquals(0.0, front.get("points").asDouble(), "boxes-front.json shows the bug: " + front.get("message"));
        assertEquals(3, front.get("images").size(), "render, reference, difference attached");
        assertTrue(front.get("images").get(0).get("url").asText().startsWith("data:image/png;base64,"));

        // A compile error: not gradable, so no attempt is charged.
        JsonNode broken = gradePrairieLearn(sfc, entry, "Box.java", buggy.replace("return", "retur n"), "broken");
        assertFalse(broken.get("gradable").asBoolean(), () -> "a compile error: " + broken.get("message"));
    }

    /**
     * Lays out /grade (student, tests, serverFilesCourse, data) and runs the entrypoint the way
     * info.json names it. Each grading gets a new folder at the same path, as each PrairieLearn
     * job gets a new /grade: the grader's cache, keyed by the files' paths, is then built once
     * for the class's gradings instead of once each.
     */
    private JsonNode gradePrairieLearn(Path sfc, String[] entry, String file, String text, String name) throws Exception {
        Path g = dir.resolve("grade");
        if (Files.exists(g)) {
            raylab.course.JavaBuild.deleteTree(g);
        }
        Files.createDirectories(g.resolve("student"));
        Files.createDirectories(g.resolve("tests"));
        Files.createDirectories(g.resolve("data"));
        Files.writeString(g.resolve("student").resolve(file), text);
        Files.writeString(g.resolve("data/data.json"), "{\"params\": {}, \"correct_answers\": {}, \"submitted_answers\": {\"_files\": []}}");
        // With the files' times, as PrairieLearn's every job has the course's files: the cache key holds the jar's time.
        FileTrees.copy(sfc, g.resolve("serverFilesCourse/raylab"), java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
        List<String> cmd = new ArrayList<>(List.of("bash", entry[0].replace("/grade/", g + "/")));
        cmd.addAll(List.of(entry).subList(1, entry.length));
        Path log = dir.resolve("pl-" + name + ".log");
        int status = run(g, Map.of("RAYLAB_GRADE_ROOT", g.toString(), "RAYLAB_CACHE", dir.resolve("cache").toString()), log,
                cmd.toArray(new String[0]));
        assertEquals(0, status, () -> "entrypoint: " + read(log));
        Path results = g.resolve("results/results.json");
        String json = Files.readString(results, StandardCharsets.UTF_8);
        assertTrue(json.getBytes(StandardCharsets.UTF_8).length <= 1_000_000, "results.json under 1 MB: " + json.length());
        return PlatformSchemas.prairieLearn(json);
    }

    @Test
    void classroom50AutograderGradesAStudentCheckout() throws Exception {
        Path root = root();
        Path starter = dir.resolve("raylab-box-student");
        Release.write(root, starter, false);
        Path c50 = dir.resolve("classroom50");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertEquals(0, Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(err, true),
                "bundle", "classroom50", "--out", c50.toString(), "--root", root.toString()), () -> "bundle: " + err);
        JsonNode fields = JSON.readTree(c50.resolve("assignment.json").toFile());
        assertEquals("{\"java\":\"21\"}", fields.get("runtime").toString());
        assertEquals(Assignments.load(root).ids().toString(), JSON.convertValue(fields.get("submission_tags"), List.class).toString());
        assertTrue(fields.get("release_assets").size() <= 50);
        Path autograder = c50.resolve("autograders/raylab/autograder.py");
        String py = Files.readString(autograder);
        assertFalse(py.contains("Hidden") || py.contains("BEGIN SOLUTION"), "nothing hidden in the public autograder");
        try (Stream<Path> s = Files.walk(c50)) {
            assertEquals(3, s.filter(Files::isRegularFile).count(), "autograder.py, assignment.json, README.md only");
        }

        Path box = starter.resolve("src/main/java/raylab/surface/Box.java");
        Files.writeString(box, reference(root, "box", "Box.java"));
        Path log = dir.resolve("c50.log");
        Map<String, String> git = Map.of("GIT_AUTHOR_NAME", "s", "GIT_AUTHOR_EMAIL", "s@example.com", "GIT_COMMITTER_NAME", "s",
                "GIT_COMMITTER_EMAIL", "s@example.com", "GIT_COMMITTER_DATE", "2026-12-01T22:15:00Z");
        assertEquals(0, run(starter, git, log, "git", "init", "-q"), () -> read(log));
        assertEquals(0, run(starter, git, log, "git", "add", "-A"), () -> read(log));
        assertEquals(0, run(starter, git, log, "git", "commit", "-qm", "box"), () -> read(log));
        assertEquals(0, run(starter, git, log, "git", "tag", "box"), () -> read(log));
        JsonNode ref = runAutograder(autograder, starter, log);
        assertEquals("2026-12-01T22:15:00Z", ref.get("datetime").asText(), "the graded commit's committer date");
        assertEquals(ref.get("max-score").asInt(), ref.get("score").asInt(), () -> "reference box: " + ref);
        assertTrue(ref.get("max-score").asInt() > 0);
        for (JsonNode t : ref.get("tests")) {
            assertEquals("box", t.get("milestone").asText(), "the tagged milestone only: " + t);
            assertFalse(t.get("test-name").asText().contains("Hidden"), t.toString());
        }
        assertTrue(Files.isRegularFile(starter.resolve("out/boxes.png")), "a release asset: out/boxes.png");
        assertTrue(fields.get("release_assets").toString().contains("\"out/boxes.png\""), fields.toString());

        Files.writeString(box, Files.readString(root.resolve("src/test/resources/submissions/bugs3/Box.java")));
        assertEquals(0, run(starter, git, log, "git", "commit", "-qam", "box again"), () -> read(log));
        assertEquals(0, run(starter, git, log, "git", "tag", "-f", "box"), () -> read(log));
        JsonNode bug = runAutograder(autograder, starter, log);
        assertTrue(bug.get("score").asInt() < bug.get("max-score").asInt(), () -> "bugs3 box: " + bug);
        boolean frontFailed = false;
        for (JsonNode t : bug.get("tests")) {
            frontFailed |= t.get("test-name").asText().equals("box: scenes/boxes-front.json") && !t.get("passed").asBoolean();
        }
        assertTrue(frontFailed, () -> "boxes-front.json shows the bug: " + bug.get("tests"));
        assertTrue(Files.isRegularFile(starter.resolve("out/boxes-front.diff.png")), "the difference image as a release asset");
    }

    private JsonNode runAutograder(Path autograder, Path checkout, Path log) throws Exception {
        Map<String, String> env = new java.util.HashMap<>(Map.of("CLASSROOM", "graphics-2027", "ASSIGNMENT", "raylab",
                "SUBMISSION_TAG", "submit/2026-12-01T22-15-00Z-abc1234", "COMMIT_URL",
                "https://github.com/graphics-2027/graphics-2027-raylab-alice/commit/abc1234", "RELEASE_URL",
                "https://github.com/graphics-2027/graphics-2027-raylab-alice/releases/tag/submit%2F2026-12-01T22-15-00Z-abc1234",
                "REVIEW_URL", "https://github.com/graphics-2027/graphics-2027-raylab-alice/compare/base...abc1234",
                "USERNAME", "alice", "OWNER", "alice", "ASSIGNMENT_TYPE", "individual"));
        env.put("PAGES_BASE_URL", "https://graphics-2027.github.io/classroom50");
        env.put("GITHUB_ACTIONS", "true");
        // Offline here (the Maven repository is already filled); on GitHub the starter's build downloads.
        env.put("MAVEN_ARGS", "-o");
        int status = run(checkout, env, log, "python3", autograder.toString());
        assertEquals(0, status, () -> "autograder.py: " + read(log));
        String json = Files.readString(checkout.resolve("result.json"));
        JsonNode r = PlatformSchemas.classroom50(json);
        assertEquals("graphics-2027", r.get("classroom").asText());
        assertEquals("raylab", r.get("assignment").asText());
        assertEquals("submit/2026-12-01T22-15-00Z-abc1234", r.get("submission").asText());
        return r;
    }

    static String read(Path log) {
        try {
            String s = Files.readString(log);
            return s.length() <= 6000 ? s : "..." + s.substring(s.length() - 6000);
        } catch (java.io.IOException e) {
            return "(no log)";
        }
    }
}
