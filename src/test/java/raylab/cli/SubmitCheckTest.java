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

    @Test
    void aMissingZipIsBadInput() {
        String[] r = run("submit-check", dir.resolve("none.zip").toString());
        assertEquals("2", r[0]);
        assertEquals("raylab: " + dir.resolve("none.zip") + ": no such file or folder", r[2].strip());
    }
}
