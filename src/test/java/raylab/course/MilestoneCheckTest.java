package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;

/** The "next step" column of raylab check. */
class MilestoneCheckTest {
    private static final Assignment.GradedScene SCENE = new Assignment.GradedScene("scenes/diffuse.json",
            "scenes/reference/diffuse.png", 2, 0.002);
    private static final Assignment LAMBERT = new Assignment("lambert", 4, "Lambert", 10, List.of("sphere", "box"),
            List.of(new Assignment.StudentFile("src/main/java/raylab/material/Lambertian.java",
                    List.of("Lambertian.diffuse"))),
            new Assignment.Tests("lambert", List.of("src/test/java/raylab/material/LambertianTest.java"), List.of(),
                    4, 4, null),
            List.of(SCENE), List.of(), false, java.nio.file.Path.of("assignments/04-lambert"));

    private static TestResult test(String method, TestResult.Status s, String message) {
        return new TestResult("id-" + method, "raylab.material.LambertianTest", method, method + "()", s, message,
                "", 1);
    }

    private static String next(List<TestResult> tests, MilestoneCheck.SceneStatus scene, String sceneMessage) {
        return new MilestoneCheck.Outcome(LAMBERT, tests, "",
                List.of(new MilestoneCheck.SceneOutcome(SCENE, scene, sceneMessage))).nextStep();
    }

    private static String notImplemented(String id, String method) {
        return new NotImplemented(id, method).getMessage();
    }

    @Test
    void ownStubSaysWhatToImplement() {
        assertEquals("implement Lambertian.diffuse", next(List.of(
                test("a", TestResult.Status.FAILED, notImplemented("lambert", "Lambertian.diffuse"))),
                MilestoneCheck.SceneStatus.NOT_IMPLEMENTED, notImplemented("lambert", "Lambertian.diffuse")));
    }

    @Test
    void anEarlierMilestoneComesFirst() {
        assertEquals("first finish milestone sphere (Sphere.intersect)", next(List.of(
                test("a", TestResult.Status.PASSED, ""),
                test("b", TestResult.Status.FAILED, notImplemented("sphere", "Sphere.intersect"))),
                MilestoneCheck.SceneStatus.NOT_IMPLEMENTED, notImplemented("sphere", "Sphere.intersect")));
    }

    @Test
    void aWrongResultNamesTheTest() {
        assertEquals("fix LambertianTest.b: expected 0.5 but was 0.25", next(List.of(
                test("a", TestResult.Status.PASSED, ""),
                test("b", TestResult.Status.FAILED, "expected 0.5 but was 0.25\nmore detail")),
                MilestoneCheck.SceneStatus.MATCH, "MATCH"));
    }

    @Test
    void aDifferentPictureSaysHowToCompare() {
        assertEquals("./raylab render scenes/diffuse.json --compare scenes/reference/diffuse.png, then look at"
                + " out/diffuse.diff.png", next(List.of(test("a", TestResult.Status.PASSED, "")),
                MilestoneCheck.SceneStatus.DIFFERS, "DIFFERS: rmse 3/255"));
    }

    @Test
    void allGoodIsDone() {
        MilestoneCheck.Outcome o = new MilestoneCheck.Outcome(LAMBERT, List.of(test("a", TestResult.Status.PASSED, "")),
                "", List.of(new MilestoneCheck.SceneOutcome(SCENE, MilestoneCheck.SceneStatus.MATCH, "MATCH")));
        assertEquals("done", o.nextStep());
        assertEquals(true, o.done());
    }

    @Test
    void compileErrorsComeFirst() {
        MilestoneCheck.Outcome o = new MilestoneCheck.Outcome(LAMBERT, List.of(),
                "fix the compile error: src/test/java/raylab/material/LambertianTest.java:3: cannot find symbol",
                List.of());
        assertEquals(o.problem(), o.nextStep());
        assertEquals(false, o.done());
    }
}
