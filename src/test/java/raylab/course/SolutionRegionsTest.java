package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Solution markers: exact student text, kept milestones, and malformed markers named by line. */
class SolutionRegionsTest {
    private static final String SAMPLE = String.join("\n",
            "class A {",
            "    int f() {",
            "        // BEGIN SOLUTION sphere",
            "        return 42;",
            "        // STUB",
            "        // throw new NotImplemented(\"sphere\", \"A.f\");",
            "        // END SOLUTION",
            "    }",
            "    // BEGIN SOLUTION sphere",
            "    private int helper() {",
            "        return 1;",
            "    }",
            "    // END SOLUTION",
            "}",
            "");

    @Test
    void studentVersionHasTheStubUncommentedAndNoHelper() {
        String expected = String.join("\n",
                "class A {",
                "    int f() {",
                "        throw new NotImplemented(\"sphere\", \"A.f\");",
                "    }",
                "}",
                "");
        assertEquals(expected, SolutionRegions.toStudent("A.java", SAMPLE, Set.of()));
    }

    @Test
    void keptMilestoneKeepsTheSolutionWithoutMarkers() {
        String expected = String.join("\n",
                "class A {",
                "    int f() {",
                "        return 42;",
                "    }",
                "    private int helper() {",
                "        return 1;",
                "    }",
                "}",
                "");
        assertEquals(expected, SolutionRegions.toStudent("A.java", SAMPLE, Set.of("sphere")));
        assertEquals(SolutionRegions.toStudent("A.java", SAMPLE, Set.of()),
                SolutionRegions.toStudent("A.java", SAMPLE, Set.of("box")), "another milestone's id keeps nothing");
    }

    @Test
    void textWithoutRegionsIsUnchanged() {
        String text = "class B {\n    int g() { return 1; }\n}";
        assertEquals(text, SolutionRegions.toStudent("B.java", text, Set.of()));
    }

    @Test
    void parseReportsRegionsWithLines() {
        List<SolutionRegions.Region> r = SolutionRegions.parse("A.java", SAMPLE);
        assertEquals(2, r.size());
        assertEquals("sphere", r.get(0).milestone());
        assertEquals(3, r.get(0).beginLine());
        assertEquals(5, r.get(0).stubLine());
        assertEquals(7, r.get(0).endLine());
        assertEquals(List.of("        return 42;"), r.get(0).solution());
        assertEquals(-1, r.get(1).stubLine(), "the helper region has no stub");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "no END                 | x;\\n// BEGIN SOLUTION sphere\\nreturn 1;                                        | A.java:2:",
        "END without BEGIN      | x;\\ny;\\n// END SOLUTION                                                      | A.java:3:",
        "STUB outside           | // STUB                                                                        | A.java:1:",
        "nested                 | // BEGIN SOLUTION sphere\\n// BEGIN SOLUTION box\\n// END SOLUTION              | A.java:2:",
        "two STUB               | // BEGIN SOLUTION sphere\\n// STUB\\n// STUB\\n// END SOLUTION                   | A.java:3:",
        "code after STUB        | // BEGIN SOLUTION sphere\\na;\\n// STUB\\nreturn 1;\\n// END SOLUTION              | A.java:4:",
        "bad milestone id       | // BEGIN SOLUTION Sphere!\\n// END SOLUTION                                      | A.java:1:",
    })
    void malformedMarkersNameTheLine(String what, String text, String where) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SolutionRegions.toStudent("A.java", text.replace("\\n", "\n"), Set.of()), what);
        assertTrue(e.getMessage().startsWith(where), what + ": expected a message starting with " + where
                + " but got: " + e.getMessage());
    }
}
