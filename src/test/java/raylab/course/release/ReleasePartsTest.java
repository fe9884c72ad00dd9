package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import raylab.course.Assignments;

/** The pieces of the release: globs, stubbing rules, the assignment.json rewrite. */
class ReleasePartsTest {
    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0} ~ {1}: {2}")
    @CsvSource({
        "src/main/java/**, src/main/java/raylab/A.java, true",
        "src/main/java/**, src/main/javax/A.java, false",
        "assignments/*/README.md, assignments/01-sphere/README.md, true",
        "assignments/*/README.md, assignments/README.md, false",
        "assignments/*/README.md, assignments/a/b/README.md, false",
        "**/*~, src/A.java~, true",
        "**/*~, A.java~, true",
        "raylab, raylab, true",
        "raylab, raylab.cmd, false",
        "docs/shading.md, docs/shadingxmd, false",
    })
    void globs(String glob, String path, boolean matches) {
        assertEquals(matches, ReleaseSpec.matchesAny(List.of(glob), path), glob + " against " + path);
    }

    /** A project with one milestone whose student file is A.java. */
    private Assignments oneMilestone() throws IOException {
        Path a = dir.resolve("assignments/01-sphere/assignment.json");
        Files.createDirectories(a.getParent());
        Files.writeString(a, """
                {"id": "sphere", "order": 1, "title": "S", "points": 2,
                 "files": [{"path": "src/A.java", "methods": ["A.f"]}],
                 "tests": {"tag": "sphere", "visible": ["src/test/java/ATest.java"], "hidden": ["grader/H.java"],
                           "visiblePoints": 1, "hiddenPoints": 1}}
                """);
        return Assignments.load(dir);
    }

    @Test
    void regionOfAnotherMilestoneIsRefused() throws IOException {
        String text = "class A {\n// BEGIN SOLUTION box\nx();\n// STUB\n// y();\n// END SOLUTION\n}\n";
        IOException e = assertThrows(IOException.class, () -> Release.stub("src/A.java", text, oneMilestone()));
        assertEquals("src/A.java:2: solution region of milestone 'box' in a file of milestone 'sphere'"
                + " (each milestone's work lives in its own files)", e.getMessage());
    }

    @Test
    void regionInAFileNoMilestoneOwnsIsRefused() throws IOException {
        String text = "class B {\n// BEGIN SOLUTION sphere\nx();\n// END SOLUTION\n}\n";
        IOException e = assertThrows(IOException.class, () -> Release.stub("src/B.java", text, oneMilestone()));
        assertTrue(e.getMessage().startsWith("src/B.java:2: solution region of milestone 'sphere' in a file that no"),
                e.getMessage());
    }

    @Test
    void studentFileWithoutRegionOrStubIsRefused() throws IOException {
        IOException none = assertThrows(IOException.class,
                () -> Release.stub("src/A.java", "class A { int f() { return 1; } }\n", oneMilestone()));
        assertTrue(none.getMessage().contains("has no solution region"), none.getMessage());
        IOException noStub = assertThrows(IOException.class, () -> Release.stub("src/A.java",
                "class A {\n// BEGIN SOLUTION sphere\nint f() { return 1; }\n// END SOLUTION\n}\n", oneMilestone()));
        assertTrue(noStub.getMessage().contains("no region of milestone 'sphere' has a // STUB part"),
                noStub.getMessage());
    }

    @Test
    void malformedRegionIsAnErrorWithItsLine() throws IOException {
        IOException e = assertThrows(IOException.class, () -> Release.stub("src/A.java",
                "class A {\n// BEGIN SOLUTION sphere\nx();\n}\n", oneMilestone()));
        assertEquals("src/A.java:2: BEGIN SOLUTION sphere has no END SOLUTION", e.getMessage());
    }

    @Test
    void assignmentLosesItsHiddenTestsAndNothingElse() throws IOException {
        oneMilestone();
        byte[] in = Files.readAllBytes(dir.resolve("assignments/01-sphere/assignment.json"));
        byte[] out = Release.withoutHiddenTests("a.json", in, 0);
        String text = new String(out, StandardCharsets.UTF_8);
        assertFalse(text.contains("hidden\""), text);
        assertFalse(text.contains("grader/"), text);
        assertTrue(text.contains("\"hiddenPoints\": 1"), text);
        assertTrue(text.contains("\"visible\": [\n      \"src/test/java/ATest.java\"\n    ]"), text);
        assertTrue(text.endsWith("}\n"), text);
        assertEquals(text, new String(Release.withoutHiddenTests("a.json", out, 0), StandardCharsets.UTF_8),
                "rewriting the result again changes nothing");
    }

    @Test
    void dataCasesStayWithTheGraderAndTheirPointsCountAsHidden() throws IOException {
        String in = "{\"id\": \"sphere\", \"points\": 10, \"tests\": {\"tag\": \"sphere\", \"visible\": [],"
                + " \"hidden\": [\"grader/x.java\"], \"visiblePoints\": 5, \"hiddenPoints\": 3, \"hiddenWeights\": {\"x\": 2}},"
                + " \"cases\": [\"cases/basic.json\"]}";
        String text = new String(Release.withoutHiddenTests("a.json", in.getBytes(StandardCharsets.UTF_8), 2),
                StandardCharsets.UTF_8);
        assertFalse(text.contains("cases"), text);
        assertFalse(text.contains("hiddenWeights"), "the weights name the hidden classes: " + text);
        assertTrue(text.contains("\"hiddenPoints\": 5"), "3 hidden points + 2 case points: " + text);
    }
}
