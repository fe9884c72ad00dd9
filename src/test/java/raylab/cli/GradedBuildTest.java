package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;
import raylab.course.GradedBuild;
import raylab.course.JavaBuild;

/**
 * A helper added to the framework's Vec3.java and used in Sphere.java compiles here and not at
 * the grader: {@code check}, {@code submit-check} (the project and a zip) name it before
 * submission in one sentence, and the grader, given the same zip, says the same sentence.
 */
class GradedBuildTest {
    static final String SPHERE = "src/main/java/raylab/surface/Sphere.java";
    static final String VEC3 = "src/main/java/raylab/math/Vec3.java";
    static final String SENTENCE = "Sphere uses Vec3.lengthCubed, which you added to Vec3.java; the grader uses the"
            + " original Vec3: this will not compile there";

    @TempDir
    static Path dir;
    static Path root = Path.of("").toAbsolutePath();
    static Path copy;
    static String sphere;
    static String vec3;

    /** A copy of the project with the release's manifest, then Vec3 given lengthCubed and Sphere using it. */
    @BeforeAll
    static void project() throws IOException {
        copy = released(root, dir.resolve("project"));
        String v = Files.readString(copy.resolve(VEC3));
        String length = "    public double length() {";
        assertTrue(v.contains(length), "Vec3.length");
        vec3 = v.replace(length, "    public double lengthCubed() {\n        return length() * lengthSquared();\n    }\n\n"
                + length);
        Files.writeString(copy.resolve(VEC3), vec3);
        String s = Files.readString(copy.resolve(SPHERE));
        String disc = "double disc = radius * radius - perp.lengthSquared();";
        assertTrue(s.contains(disc), "Sphere's discriminant");
        sphere = s.replace(disc, "double disc = radius * radius - perp.lengthCubed() / perp.length();");
        Files.writeString(copy.resolve(SPHERE), sphere);
    }

    /** A copy of the project at {@code root} in {@code to}, as a starter is: with the release's manifest. */
    static Path released(Path root, Path to) throws IOException {
        Path copy = CheckFeedbackTest.copyLayout(root, to);
        SortedMap<String, byte[]> released = new TreeMap<>();
        FileTrees.copy(root.resolve("src/main/java"), copy.resolve("src/main/java"));
        try (Stream<Path> s = Files.walk(root.resolve("src/main/java"))) {
            for (Path p : s.filter(Files::isRegularFile).toList()) {
                released.put(root.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
            }
        }
        Set<String> students = SubmitCheckCommand.studentFiles(Assignments.load(root).all());
        Files.writeString(copy.resolve(GradedBuild.MANIFEST), GradedBuild.manifestText(released, students,
                JavaBuild.ownClassPath()));
        return copy;
    }

    static Path zip(String name) throws IOException {
        Path zip = dir.resolve(name);
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            for (String[] e : new String[][] {{"Sphere.java", sphere}, {"Vec3.java", vec3}}) {
                z.putNextEntry(new ZipEntry(e[0]));
                z.write(e[1].getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        return zip;
    }

    static String[] child(String... args) throws Exception {
        return childIn(copy, args);
    }

    /** {@code raylab ARGS} in a JVM of its own, in {@code project}: exit status, standard output, standard error. */
    static String[] childIn(Path project, String... args) throws Exception {
        Path out = Files.createTempFile(project.getParent(), "out", ".txt");
        Path err = Files.createTempFile(project.getParent(), "err", ".txt");
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(project.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        assertTrue(p.waitFor(10, TimeUnit.MINUTES), "raylab " + String.join(" ", args) + " finished");
        return new String[] {Integer.toString(p.exitValue()), Files.readString(out), Files.readString(err)};
    }

    @Test
    void theSharedAnalysisNamesTheChangedFileAndTheUse() throws IOException {
        GradedBuild.Drift d = GradedBuild.check(copy, Map.of(SPHERE, sphere),
                SubmitCheckCommand.studentFiles(Assignments.load(copy).all()), JavaBuild.ownClassPath());
        assertEquals(List.of(VEC3), d.changedFiles(), "changed framework files");
        assertEquals(List.of(), d.addedFiles(), "added framework files");
        assertEquals(List.of(SENTENCE), d.uses(), "the uses of what only the student's Vec3 has");
        // Without the use, only the change is said.
        String plain = Files.readString(root.resolve(SPHERE));
        GradedBuild.Drift none = GradedBuild.check(copy, Map.of(SPHERE, plain),
                SubmitCheckCommand.studentFiles(Assignments.load(copy).all()), JavaBuild.ownClassPath());
        assertEquals(List.of(), none.uses(), "the reference Sphere uses nothing new");
    }

    @Test
    void submitCheckOfTheProjectNamesIt() throws IOException {
        Assignment a = Assignments.load(copy).byId("sphere").orElseThrow();
        StringWriter text = new StringWriter();
        int status = SubmitCheckCommand.project(new PrintWriter(text, true), copy, List.of(a), List.of());
        String out = text.toString();
        assertEquals(Main.FAILED, status, out);
        assertTrue(out.contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), out);
        assertTrue(out.contains("NOTE: you changed " + VEC3 + ": the grader uses the original, so your change does"
                + " not count there."), out);
    }

    @Test
    void submitCheckOfAZipNamesItAndCheckToo() throws Exception {
        String[] r = child("submit-check", zip("with-vec3.zip").toString());
        assertEquals("1", r[0], "exit status: " + r[1] + r[2]);
        assertTrue(r[1].contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), r[1]);
        String[] c = child("check", "sphere", "--threads", "1");
        assertEquals("1", c[0], "exit status: " + c[1] + c[2]);
        assertTrue(c[1].contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), c[1]);
        // The edit is the framework's, not another milestone's: the row scores sphere as the grader will.
        String row = c[1].lines().filter(l -> l.startsWith("sphere ")).findFirst().orElse("(no row for sphere)");
        assertTrue(row.matches("sphere +(\\d+)/\\1 +(\\d+)/\\2 +0/[0-9.]+ +will not compile at the grader \\(below\\): 0 points there"),
                "the table's row: every test passes and every scene matches in the checkout, and 0 points: " + row);
    }

    @Test
    void aZipThatDoesNotCompileIsSaidSo() throws Exception {
        Path zip = dir.resolve("broken.zip");
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            z.putNextEntry(new ZipEntry("Box.java"));
            z.write("package raylab.surface;\npublic class Box { int x = ; }\n".getBytes(StandardCharsets.UTF_8));
            z.closeEntry();
        }
        StringWriter out = new StringWriter();
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(new StringWriter(), true), "submit-check",
                zip.toString());
        assertEquals(Main.FAILED, status, out.toString());
        assertTrue(out.toString().contains("DOES NOT COMPILE (as the grader builds it, so the milestone would score 0):\n"
                + "  src/main/java/raylab/surface/Box.java:2: illegal start of expression"), out.toString());
    }

    @Test
    void theGraderSaysTheSameSentence() throws Exception {
        Path results = dir.resolve("results");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", zip("to-grade.zip").toString(), "--out",
                results.toString(), "--root", root.toString(), "--quiet", "--milestone", "sphere", "--test-timeout", "5",
                "--milestone-timeout", "60", "--scene-timeout", "30", "--heap", "256", "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        assertTrue(r.toString().contains(SENTENCE), "the grader's report: " + r);
        assertEquals(0.0, r.get("score").asDouble(), "the grader's score of sphere, which does not compile there: " + r);
    }
}
