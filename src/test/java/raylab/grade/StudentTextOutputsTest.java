package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.grade.platform.PrairieLearn;
import raylab.scene.Display;

/**
 * Issue 35 item 7: student text (failure messages, printed output, notes) reaches no output with
 * its control characters, and none longer than {@link Display#TEXT_MAX}: results.json
 * (Gradescope), PrairieLearn's results.json, junit.xml, report.html and the console table, all
 * written from one {@link GradeReport}, which makes the text safe once ({@link Display#text}).
 */
class StudentTextOutputsTest {
    static final String HOSTILE = "got\u0000 rgb\u001b[2J\u001b[31m red\rOVERWRITTEN\r\nline 2\u202e)gnp.exe\ttab\u0007";
    static final String SAFE = "got\\u0000 rgb\\u001b[2J\\u001b[31m red\\rOVERWRITTEN\nline 2\\u202e)gnp.exe\ttab\\u0007";

    @Test
    void displayTextKeepsLinesAndEscapesTheRest() {
        assertEquals(SAFE, Display.text(HOSTILE));
        assertEquals("plain\nlines\tand tabs \uD83D\uDE00 é", Display.text("plain\nlines\tand tabs \uD83D\uDE00 é"));
        assertEquals("lone \\ud83d high", Display.text("lone \uD83D high"));
        assertEquals(null, Display.text(null));
        assertEquals(Display.text(SAFE), SAFE, "escaped text stays as it is: made safe twice is made safe once");
        String longText = "x".repeat(Display.TEXT_MAX + 10);
        assertEquals("x".repeat(Display.TEXT_MAX) + "\n(10 more characters cut)", Display.text(longText));
        // A pair at the cut is kept whole (the text then has one more char than TEXT_MAX).
        String pairAtCut = "x".repeat(Display.TEXT_MAX - 1) + "\uD83D\uDE00" + "yz";
        assertEquals("x".repeat(Display.TEXT_MAX - 1) + "\uD83D\uDE00\n(2 more characters cut)", Display.text(pairAtCut));
    }

    static GradeReport report() {
        String huge = "y".repeat(200_000);
        GradeReport.Test failed = new GradeReport.Test("sphere", "sphere: a ray from outside hits", GradeReport.Kind.VISIBLE,
                2, 0, false, HOSTILE, HOSTILE + "\n" + huge, "visible", 12, "SphereTest.java", null, HOSTILE);
        GradeReport.Test passed = new GradeReport.Test("sphere", "sphere: misses", GradeReport.Kind.VISIBLE, 1, 1, true,
                "", HOSTILE, "visible", 3, "SphereTest.java", null);
        GradeReport.Milestone m = new GradeReport.Milestone("sphere", "Ray-sphere intersection", List.of(HOSTILE),
                List.of(failed, passed));
        return new GradeReport(List.of(m), List.of("src/main/java/raylab/surface/Sphere.java <- Sphere.java"),
                List.of(HOSTILE), List.of(HOSTILE), 1.5);
    }

    /** The unsafe characters of {@code s} (controls other than line feed and tab), as code points. */
    static List<String> unsafe(String where, String s) {
        List<String> bad = new ArrayList<>();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if ((c < 0x20 && c != '\n' && c != '\t') || (c >= 0x7f && c <= 0x9f) || c == '\u202e') {
                bad.add(where + "[" + i + "]=U+" + Integer.toHexString(c));
            }
        }
        return bad;
    }

    static void strings(String where, JsonNode n, Map<String, String> out) {
        if (n.isTextual()) {
            out.put(where, n.asText());
        } else if (n.isContainerNode()) {
            var it = n.fields();
            while (it.hasNext()) {
                var e = it.next();
                strings(where + "." + e.getKey(), e.getValue(), out);
            }
            for (int i = 0; n.isArray() && i < n.size(); i++) {
                strings(where + "[" + i + "]", n.get(i), out);
            }
        }
    }

    @Test
    void noOutputCarriesAControlCharacterOrUnboundedText() throws IOException {
        GradeReport r = report();
        ObjectMapper json = new ObjectMapper();
        Map<String, String> texts = new java.util.LinkedHashMap<>();
        strings("gradescope", json.readTree(Reports.gradescope(r)), texts);
        strings("prairielearn", json.readTree(PrairieLearn.results(r, true)), texts);
        texts.put("junit.xml", Reports.junitXml(r));
        texts.put("report.html", Reports.html(r));
        ByteArrayOutputStream console = new ByteArrayOutputStream();
        Reports.table(r, new PrintStream(console, true, StandardCharsets.UTF_8));
        texts.put("console", console.toString(StandardCharsets.UTF_8));
        List<String> bad = new ArrayList<>();
        texts.forEach((where, s) -> bad.addAll(unsafe(where, s)));
        assertEquals(List.of(), bad, "control characters in the outputs");
        // What the student wrote is still there, escaped: a NUL shows as \u0000, ESC as \u001b.
        String gradescopeTests = json.readTree(Reports.gradescope(r)).get("tests").toString();
        assertTrue(gradescopeTests.contains("\\\\u001b[31m"), "the escape sequence shown escaped: " + gradescopeTests.substring(0, 400));
        for (GradeReport.Test t : r.milestones().get(0).tests()) {
            assertTrue(t.output().length() <= Display.TEXT_MAX + 40, "output bounded: " + t.output().length());
        }
        assertTrue(r.milestones().get(0).tests().get(0).output().endsWith(" more characters cut)"),
                "the cut is said");
        assertEquals(SAFE, r.milestones().get(0).tests().get(0).message());
        assertEquals(SAFE, r.milestones().get(0).tests().get(0).note());
        assertEquals(List.of(SAFE), r.milestones().get(0).notes());
        assertEquals(List.of(SAFE), r.notes());
        assertEquals(List.of(SAFE), r.ignored());
    }
}
