package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.MilestoneCheck;

/** check says the same word for a scene in its scene list and in its points table; lines are cut between words. */
class CheckWordsTest {
    @Test
    void aSceneNotImplementedIsSoInThePointsTableToo() throws Exception {
        Path root = Path.of("").toAbsolutePath();
        Assignment lambert = Assignments.load(root).byId("lambert").orElseThrow();
        Assignment.GradedScene g = lambert.scenes().get(0);
        MilestoneCheck.Outcome o = new MilestoneCheck.Outcome(lambert, List.of(), "", List.of(new MilestoneCheck.SceneOutcome(
                g, MilestoneCheck.SceneStatus.NOT_IMPLEMENTED, "not implemented yet: write Shading.shade")),
                GradingPlan.of(root, lambert));
        StringWriter text = new StringWriter();
        CheckCommand.printDetails(new PrintWriter(text, true), o);
        String out = text.toString();
        assertTrue(out.contains("  NOT IMPLEMENTED " + g.scene() + ": "), "the scene list:\n" + out);
        assertTrue(out.lines().anyMatch(l -> l.startsWith("  NOT IMPLEMENTED 0/") && l.contains(g.scene())),
                "the points table says the same:\n" + out);
        assertTrue(out.lines().noneMatch(l -> l.startsWith("  DIFFERS") && l.contains(g.scene())), out);
    }

    @Test
    void aLongLineIsCutBetweenWords() {
        String message = "expected: hit at t=1.5 on the far side of the sphere, because the ray starts inside it and"
                + " the nearer root lies behind its start; got: no hit at all, the record is unchanged: Check it";
        String cut = MilestoneCheck.oneLine(message, 160);
        assertEquals(message.substring(0, message.lastIndexOf(' ', 156)) + " ...", cut);
        assertTrue(cut.length() <= 160, cut);
        String word = cut.substring(0, cut.length() - 4);
        assertTrue(message.startsWith(word) && message.charAt(word.length()) == ' ', "cut at a space: " + cut);
        assertEquals("short", MilestoneCheck.oneLine("short", 160));
    }
}
