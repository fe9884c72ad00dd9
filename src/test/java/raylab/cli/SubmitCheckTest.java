package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.JavaBuild;

/** {@code raylab submit-check}: exactly the files the grader takes, and a warning for the rest of a zip. */
class SubmitCheckTest {
    @TempDir
    Path dir;

    String[] run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new String[] {Integer.toString(status), out.toString(), err.toString()};
    }

    @Test
    void aZipListsTheGradedFileAndWarnsAboutTheRest() throws Exception {
        Path zip = dir.resolve("whole-repo.zip");
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            for (String name : new String[] {"raylab/src/main/java/raylab/surface/Sphere.java", "raylab/README.md",
                "raylab/target/classes/raylab/surface/Sphere.class"}) {
                z.putNextEntry(new ZipEntry(name));
                z.write((name.endsWith(".java") ? Files.readString(Path.of("src/main/java/raylab/surface/Sphere.java"))
                        : "x").getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        String[] r = run("submit-check", zip.toString());
        assertEquals("0", r[0], "exit status; stderr: " + r[2]);
        String out = r[1];
        assertTrue(out.startsWith("The grader takes 1 file from "), out);
        assertTrue(out.lines().anyMatch(l -> l.matches("  sphere +src/main/java/raylab/surface/Sphere.java +from "
                + "raylab/src/main/java/raylab/surface/Sphere.java")), "the graded file and its place in the zip:\n" + out);
        assertTrue(out.lines().anyMatch(l -> l.matches("  box +src/main/java/raylab/surface/Box.java +not in the submission")),
                out);
        assertTrue(out.contains("WARNING: 2 other files are in the submission and will not be graded"), out);
        assertTrue(out.contains("  raylab/README.md: not a Java source file"), out);
        assertTrue(out.contains("  raylab/target/classes/raylab/surface/Sphere.class: not a Java source file"), out);
    }

    @Test
    void theProjectListsEveryStudentFile() {
        String[] r = run("submit-check");
        assertEquals("0", r[0], "exit status; stderr: " + r[2]);
        for (String f : StudentFault.DEFAULT_FILES) {
            assertTrue(r[1].lines().anyMatch(l -> l.contains(f) && l.matches(".* finished: its \\d+ visible tests pass")),
                    f + " listed as finished (the reference passes its tests):\n" + r[1]);
        }
    }

    @Test
    void twoCopiesOfAGradedFileAreRefusedNamingBoth() throws Exception {
        Path zip = dir.resolve("two.zip");
        String sphere = Files.readString(Path.of("src/main/java/raylab/surface/Sphere.java"));
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            for (String name : new String[] {"backup/Sphere.java", "Sphere.java"}) {
                z.putNextEntry(new ZipEntry(name));
                z.write(sphere.getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        String[] r = run("submit-check", zip.toString());
        assertEquals("1", r[0], "exit status; stdout: " + r[1] + " stderr: " + r[2]);
        assertTrue(r[1].contains("REFUSED: 2 copies of Sphere.java in the submission: backup/Sphere.java and Sphere.java;"
                + " the grader would grade neither. Remove all but one (at src/main/java/raylab/surface/Sphere.java)."),
                r[1]);
        assertTrue(r[1].lines().anyMatch(l -> l.matches("  sphere +src/main/java/raylab/surface/Sphere.java +NOT GRADED: 2 "
                + "copies, none at this path \\(see below\\)")), r[1]);
    }

    /** A file that no longer throws NotImplemented but fails tests is not called finished, and they are named. */
    @Test
    void aWrittenFileWithFailingTestsIsNotFinished() throws Exception {
        Path root = Path.of("").toAbsolutePath();
        Path copy = CheckFeedbackTest.copyLayout(root, dir.resolve("project"));
        String buggy = Files.readString(root.resolve("src/test/resources/submissions/bugs2/Sphere.java"));
        assertTrue(buggy.contains("BUG: the far root is never tried"), "the planted bug");
        Path sphereFile = copy.resolve("src/main/java/raylab/surface/Sphere.java");
        Files.createDirectories(sphereFile.getParent());
        Files.writeString(sphereFile, buggy);
        Path overlay = dir.resolve("student-classes");
        raylab.course.JavaBuild.Result compiled = raylab.course.MilestoneBuild.compileOverlay(
                Map.of("raylab/surface/Sphere.java", buggy), dir.resolve("student-src"),
                raylab.course.JavaBuild.ownClassPath(), overlay);
        assertTrue(compiled.success(), compiled.errors().toString());
        raylab.course.Assignment sphere = raylab.course.Assignments.load(copy).byId("sphere").orElseThrow();

        StringWriter text = new StringWriter();
        PrintWriter w = new PrintWriter(text, true);
        SubmitCheckCommand.project(w, copy, List.of(sphere), List.of(overlay));
        String out = text.toString();
        assertTrue(out.lines().anyMatch(l -> l.matches("  sphere +src/main/java/raylab/surface/Sphere.java +NOT FINISHED: "
                + "\\d+ of \\d+ visible tests fail \\(below\\)")), "not finished:\n" + out);
        assertTrue(out.contains("  FAIL \"a ray starting inside hits the far side (the farther root), normal outward\""),
                "the failing test named as in the handout:\n" + out);
        assertTrue(!out.contains("written"), out);
    }

    static void git(Path repo, String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of("git", "-C", repo.toString(), "-c", "user.name=student",
                "-c", "user.email=student@example.com", "-c", "commit.gpgsign=false", "-c", "tag.gpgsign=false"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), "git " + String.join(" ", args) + ": " + out);
    }

    /** Classroom 50 grades the tag's commit: an edit left out of it, and a file never added, are named. */
    @Test
    void editsLeftOutOfTheMilestonesTagAreNamed() throws Exception {
        Path repo = Files.createDirectories(dir.resolve("repo"));
        String sphere = "src/main/java/raylab/surface/Sphere.java";
        String box = "src/main/java/raylab/surface/Box.java";
        Files.createDirectories(repo.resolve(sphere).getParent());
        Files.copy(Path.of(sphere), repo.resolve(sphere));
        git(repo, "init", "-q");
        git(repo, "add", sphere);
        git(repo, "commit", "-q", "-m", "sphere");
        git(repo, "tag", "sphere");
        git(repo, "tag", "box");
        List<raylab.course.Assignment> all = raylab.course.Assignments.load(Path.of("")).all();
        assertEquals(List.of(), SubmitCheckCommand.tagWarnings(repo, all), "the working tree is what the tags hold");

        Files.writeString(repo.resolve(sphere), Files.readString(repo.resolve(sphere)) + "// a fix after the tag\n");
        Files.copy(Path.of(box), repo.resolve(box));
        assertEquals(List.of("WARNING: " + sphere + " differs from the commit of the tag 'sphere', which Classroom 50"
                + " grades: commit it, then move the tag (git tag -f sphere && git push -f origin sphere)",
                "WARNING: " + box + " is not in the commit of the tag 'box', which Classroom 50 grades: git add it,"
                + " commit, then move the tag (git tag -f box && git push -f origin box)"),
                SubmitCheckCommand.tagWarnings(repo, all));
    }

    /** submit-check TAG: the files of the tag's commit, compiled as the grader builds them. */
    @Test
    void aTagIsCheckedAsItsCommit() throws Exception {
        Path repo = Files.createDirectories(dir.resolve("tagged"));
        CheckFeedbackTest.copyLayout(Path.of("").toAbsolutePath(), repo);
        String box = "src/main/java/raylab/surface/Box.java";
        Files.createDirectories(repo.resolve(box).getParent());
        Files.writeString(repo.resolve(box), "package raylab.surface;\npublic class Box { int x = ; }\n");
        git(repo, "init", "-q");
        git(repo, "add", box);
        git(repo, "commit", "-q", "-m", "box");
        git(repo, "tag", "box");
        Files.copy(Path.of(box), repo.resolve(box), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main", "submit-check", "box"));
        Process p = new ProcessBuilder(cmd).directory(repo.toFile()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(1, p.waitFor(), out);
        assertTrue(out.startsWith("The commit of the tag 'box':\nThe grader takes 1 file from box:"), out);
        assertTrue(out.contains("DOES NOT COMPILE (as the grader builds it, so the milestone would score 0):\n"
                + "  " + box + ":2: illegal start of expression"), "the tagged text, not the fixed working tree:\n" + out);
    }

    @Test
    void aMissingZipIsBadInput() {
        String[] r = run("submit-check", dir.resolve("none.zip").toString());
        assertEquals("2", r[0]);
        assertEquals("raylab: " + dir.resolve("none.zip") + ": no such file, folder or tag", r[2].strip());
    }
}
