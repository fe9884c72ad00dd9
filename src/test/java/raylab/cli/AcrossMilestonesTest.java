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
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradedBuild;
import raylab.course.JavaBuild;

/**
 * A helper a student adds to one graded file and uses in another milestone's (Box.java calling
 * {@code Sphere.later}, which the student wrote in Sphere.java) compiles in the student's project
 * and not at the grader, which compiles each milestone's files with its own classes of the other
 * milestones. {@code check} and {@code submit-check} say so before submission, in the sentence the
 * grader's report gives. Before, both said "finished" and the grader scored the box milestone 0
 * ("your code does not compile").
 */
class AcrossMilestonesTest {
    static final String SPHERE = "src/main/java/raylab/surface/Sphere.java";
    static final String BOX = "src/main/java/raylab/surface/Box.java";
    static final String SENTENCE = "Box uses Sphere.later, which you added to Sphere.java; the grader compiles Box.java"
            + " with its own Sphere.java, not yours (each milestone is graded on its own): this will not compile there;"
            + " put what Box needs in Box.java";

    @TempDir
    static Path dir;
    static Path root = Path.of("").toAbsolutePath();
    static Path copy;
    static String sphere;
    static String box;

    /** A copy of the project with the release's manifest; Sphere given a public helper, Box using it. */
    @BeforeAll
    static void project() throws IOException {
        copy = GradedBuildTest.released(root, dir.resolve("project"));
        String s = Files.readString(copy.resolve(SPHERE));
        String convex = "    @Override\n    public boolean isConvex() {";
        assertTrue(s.contains(convex), "Sphere.isConvex");
        sphere = s.replace(convex, "    /** The later of two times. */\n    public static double later(double a, double b) {\n"
                + "        return Math.max(a, b);\n    }\n\n" + convex);
        Files.writeString(copy.resolve(SPHERE), sphere);
        String b = Files.readString(copy.resolve(BOX));
        String enter = "double tEnter = Double.NEGATIVE_INFINITY;";
        assertTrue(b.contains(enter), "Box's entry time");
        box = b.replace(enter, "double tEnter = Sphere.later(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY);");
        Files.writeString(copy.resolve(BOX), box);
    }

    static Map<String, String> milestoneOf() throws IOException {
        return SubmitCheckCommand.milestoneOf(Assignments.load(copy).all());
    }

    @Test
    void theSharedAnalysisNamesTheUseAcrossMilestones() throws IOException {
        Map<String, String> all = Map.of(SPHERE, sphere, BOX, box);
        assertEquals(List.of(SENTENCE), GradedBuild.acrossMilestones(copy, Map.of(BOX, box), all, milestoneOf(),
                JavaBuild.ownClassPath()), "box's file uses what only the student's Sphere has");
        assertEquals(List.of(), GradedBuild.acrossMilestones(copy, Map.of(SPHERE, sphere), all, milestoneOf(),
                JavaBuild.ownClassPath()), "the student's Sphere uses nothing of Box");
        // A class of its own in Sphere.java, which Box names and Sphere does not.
        String withClass = sphere + "\nfinal class Quadratic {\n    static double later(double a, double b) {\n"
                + "        return Math.max(a, b);\n    }\n}\n";
        String boxWithClass = box.replace("Sphere.later(", "Quadratic.later(");
        String rest = ", which you added to Sphere.java; the grader compiles Box.java with its own Sphere.java, not yours"
                + " (each milestone is graded on its own): this will not compile there; put what Box needs in Box.java";
        assertEquals(List.of("Box uses Quadratic.later" + rest, "Box uses Quadratic" + rest),
                GradedBuild.acrossMilestones(copy, Map.of(BOX, boxWithClass), Map.of(SPHERE, withClass, BOX, boxWithClass),
                        milestoneOf(), JavaBuild.ownClassPath()), "a class of its own in Sphere.java, and its member");
        String plainBox = Files.readString(root.resolve(BOX));
        assertEquals(List.of(), GradedBuild.acrossMilestones(copy, Map.of(BOX, plainBox), Map.of(SPHERE, sphere, BOX,
                plainBox), milestoneOf(), JavaBuild.ownClassPath()), "the reference Box uses only what every Sphere has");
    }

    @Test
    void submitCheckOfTheProjectNamesIt() throws IOException {
        List<Assignment> both = List.of(Assignments.load(copy).byId("sphere").orElseThrow(),
                Assignments.load(copy).byId("box").orElseThrow());
        StringWriter text = new StringWriter();
        int status = SubmitCheckCommand.project(new PrintWriter(text, true), copy, both, List.of());
        String out = text.toString();
        assertEquals(Main.FAILED, status, out);
        assertTrue(out.contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), out);
        // Box's row does not say "finished" above that line; Sphere's, which compiles there, does.
        assertTrue(out.contains("  box      " + BOX + " ".repeat(46 - BOX.length())
                + " WILL NOT COMPILE AT THE GRADER (below): 0 points there\n"), out);
        assertTrue(out.matches("(?s).*  sphere   " + java.util.regex.Pattern.quote(SPHERE)
                + " +finished: its \\d+ visible tests pass\n.*"), out);
    }

    /**
     * {@code check box} names it, and neither its table nor Classroom 50's result.json (feedback on a
     * Release) gives the box tests' points, which pass in the checkout: the grader will score box 0.
     * Before, the table said "done" with 3.6/3.6 points above the WILL NOT COMPILE line, and
     * result.json gave 360 of 360.
     */
    @Test
    void checkOfTheMilestoneNamesItAndScoresItAsTheGraderWill() throws Exception {
        Path result = dir.resolve("result.json");
        String[] c = GradedBuildTest.childIn(copy, "check", "box", "--threads", "1", "--classroom50", result.toString());
        assertEquals("1", c[0], "exit status: " + c[1] + c[2]);
        assertTrue(c[1].contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), c[1]);
        String row = c[1].lines().filter(l -> l.startsWith("box ")).findFirst().orElse("(no row for box)");
        assertTrue(row.matches("box +(\\d+)/\\1 +(\\d+)/\\2 +0/[0-9.]+ +will not compile at the grader \\(below\\): 0 points there"),
                "the table's row: every test passes and every scene matches in the checkout, and 0 points: " + row);
        JsonNode r = raylab.grade.platform.PlatformSchemas.classroom50(Files.readString(result));
        assertEquals(0, r.get("score").asLong(), "Classroom 50's score: " + r);
        assertTrue(r.get("max-score").asLong() > 0, "the box items are all there: " + r);
        int passedHere = 0;
        for (JsonNode t : r.get("tests")) {
            assertEquals("box", t.get("milestone").asText(), t.toString());
            assertEquals(false, t.get("passed").asBoolean(), t.toString());
            assertEquals(0, t.get("score").asLong(), t.toString());
            assertEquals("will not compile at the grader: " + SENTENCE + " (it passes in this checkout, whose build uses"
                    + " your own files)", t.get("message").asText(), t.toString());
            passedHere++;
        }
        assertTrue(passedHere > 10, "box's tests, data cases and scenes: " + passedHere);
    }

    @Test
    void ofSeveralMilestonesOnlyTheOneThatUsesTheOtherWillNotCompile() throws IOException {
        List<Assignment> all = Assignments.load(copy).all();
        List<Assignment> both = List.of(Assignments.load(copy).byId("sphere").orElseThrow(),
                Assignments.load(copy).byId("box").orElseThrow());
        GradedBuild.Drift d = SubmitCheckCommand.drift(copy, SubmitCheckCommand.projectFiles(copy, both),
                SubmitCheckCommand.projectFiles(copy, all), all, JavaBuild.ownClassPath());
        assertEquals(Map.of("box", List.of(SENTENCE)), SubmitCheckCommand.wontCompile(copy, both, all, d,
                JavaBuild.ownClassPath()),
                "box uses what only the student's Sphere has; sphere compiles at the grader as it is");
    }

    @Test
    void submitCheckOfAZipAndTheGraderSayTheSameSentence() throws Exception {
        Path zip = dir.resolve("both.zip");
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            for (String[] e : new String[][] {{"Sphere.java", sphere}, {"Box.java", box}}) {
                z.putNextEntry(new ZipEntry(e[0]));
                z.write(e[1].getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        String[] c = GradedBuildTest.childIn(copy, "submit-check", zip.toString());
        assertEquals("1", c[0], "exit status: " + c[1] + c[2]);
        assertTrue(c[1].contains("WILL NOT COMPILE AT THE GRADER: " + SENTENCE + "."), c[1]);

        Path results = dir.resolve("results");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", zip.toString(), "--out", results.toString(),
                "--root", root.toString(), "--quiet", "--milestone", "box", "--test-timeout", "5",
                "--milestone-timeout", "60", "--scene-timeout", "30", "--heap", "256", "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        assertTrue(r.toString().contains(SENTENCE), "the grader's report: " + r);
    }
}
