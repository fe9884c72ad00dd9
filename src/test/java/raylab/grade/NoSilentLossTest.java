package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * No point is lost silently: for every realistic single bug of the corpus
 * (src/test/resources/submissions/mistakes/corpus.json: the older bugsN files and the mistakes/
 * folders, one bug each) whose grade loses points, a visible item (visible test, visible data
 * case or scene) fails before the due date, and a visible test's or data case's message names
 * the mistake (one of the corpus entry's "names"). And hints are chosen by evidence: each hint
 * is shown for the bug that makes its mistake and not for one that makes another mistake in the
 * same tests. Bugs are graded through {@code raylab grade}, several milestones per grading (at
 * most one bug per student file), only the milestones they belong to.
 */
@ExtendWith(SharedGraderCache.class)
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class NoSilentLossTest {
    static final ObjectMapper JSON = new ObjectMapper();

    /** One bug: its file (relative to submissions/), milestone, what it gets wrong, words that name it. */
    record Bug(String file, String milestone, String mistake, List<String> names) {
    }

    /** Per bug (by file): its milestone's graded items in results.json. */
    final Map<String, List<JsonNode>> graded = new LinkedHashMap<>();
    final List<Bug> bugs = new ArrayList<>();

    @TempDir
    static Path dir;

    static Path resources() {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        return root.resolve("src/test/resources/submissions");
    }

    @BeforeAll
    void gradeTheCorpus() throws IOException {
        for (JsonNode b : JSON.readTree(resources().resolve("mistakes/corpus.json").toFile())) {
            List<String> names = new ArrayList<>();
            b.get("names").forEach(n -> names.add(n.asText()));
            bugs.add(new Bug(b.get("file").asText(), b.get("milestone").asText(), b.get("mistake").asText(), names));
        }
        // Rounds: each takes at most one bug per student file.
        List<List<Bug>> rounds = new ArrayList<>();
        for (Bug bug : bugs) {
            String name = Path.of(bug.file()).getFileName().toString();
            List<Bug> round = rounds.stream().filter(r -> r.stream().noneMatch(
                    o -> Path.of(o.file()).getFileName().toString().equals(name))).findFirst().orElse(null);
            if (round == null) {
                round = new ArrayList<>();
                rounds.add(round);
            }
            round.add(bug);
        }
        int n = 0;
        for (List<Bug> round : rounds) {
            Path d = Files.createDirectories(dir.resolve("round" + n++));
            Path overlay = Files.createDirectories(d.resolve("overlay"));
            List<String> milestones = new ArrayList<>();
            for (Bug bug : round) {
                Path f = resources().resolve(bug.file());
                Files.copy(f, overlay.resolve(f.getFileName()));
                if (!milestones.contains(bug.milestone())) {
                    milestones.add(bug.milestone());
                }
            }
            JsonNode r = LectureMethodsTest.grade(d, overlay.toString(), milestones.toArray(String[]::new));
            for (Bug bug : round) {
                List<JsonNode> items = new ArrayList<>();
                for (JsonNode t : r.get("tests")) {
                    if (t.get("tags").get(0).asText().equals(bug.milestone())) {
                        items.add(t);
                    }
                }
                graded.put(bug.file(), items);
            }
        }
    }

    static boolean lost(JsonNode t) {
        return t.get("score").asDouble() < t.get("max_score").asDouble();
    }

    static boolean visible(JsonNode t) {
        return t.get("visibility").asText().equals("visible");
    }

    @Test
    void everyBugThatLosesPointsFailsAVisibleItemWhoseMessageNamesTheMistake() {
        StringBuilder silent = new StringBuilder();
        for (Bug bug : bugs) {
            List<JsonNode> items = graded.get(bug.file());
            double lostPoints = items.stream().mapToDouble(t -> t.get("max_score").asDouble() - t.get("score").asDouble()).sum();
            List<JsonNode> visibleFailures = items.stream().filter(t -> visible(t) && lost(t)).toList();
            boolean named = visibleFailures.stream().anyMatch(t -> !t.get("tags").get(1).asText().equals("scene")
                    && bug.names().stream().anyMatch(w -> t.get("output").asText().toLowerCase(Locale.ROOT)
                            .contains(w.toLowerCase(Locale.ROOT))));
            System.out.printf("%-48s %-9s loses %5.2f; %2d visible item(s) fail%s%n", bug.file(), bug.milestone(),
                    lostPoints, visibleFailures.size(), named ? ", one names the mistake" : "");
            if (lostPoints > 0 && !named) {
                silent.append("\n  ").append(bug.file()).append(" (").append(bug.mistake()).append(") loses ")
                        .append(String.format(Locale.ROOT, "%.2f", lostPoints)).append(" points; visible failures: ")
                        .append(visibleFailures.stream().map(t -> t.get("name").asText()).toList());
            }
        }
        assertTrue(silent.length() == 0, "points lost without a visible message naming the mistake:" + silent);
    }

    /** The visible outputs of a bug's failing items, joined. */
    String visibleOutput(String file) {
        StringBuilder b = new StringBuilder();
        for (JsonNode t : graded.get(file)) {
            if (visible(t) && lost(t)) {
                b.append(t.get("name").asText()).append(": ").append(t.get("output").asText()).append("\n");
            }
        }
        return b.toString();
    }

    /** The output of one visible test of a bug, by the start of its name ("box: d parallel ..."). */
    String testOutput(String file, String name) {
        for (JsonNode t : graded.get(file)) {
            if (t.get("name").asText().startsWith(name)) {
                return t.get("output").asText();
            }
        }
        throw new AssertionError("no graded item " + name + " for " + file);
    }

    void shown(String file, String test, String hint) {
        String out = testOutput(file, test);
        assertTrue(out.contains(hint), file + " should get the hint '" + hint + "' in '" + test + "':\n" + out);
    }

    void notShown(String file, String test, String hint) {
        String out = testOutput(file, test);
        assertFalse(out.contains(hint), file + " must not get the hint '" + hint + "' in '" + test + "':\n" + out);
    }

    @Test
    void theZeroComponentHintOnlyWhenAZeroComponentIsMishandled() {
        String test = "box: d parallel to two slabs, inside both: hit";
        String hint = "when d_x = 0, the ray is inside the x slab";
        shown("mistakes/box-zero-direction-misses/Box.java", test, hint);
        notShown("mistakes/box-normal-sign/Box.java", test, hint); // fails the same test, with a wrong normal
    }

    @Test
    void theNormalSignHintOnlyForAWrongNormalSign() {
        String test = "box: d parallel to two slabs, inside both: hit";
        String hint = "the normal must point out of the surface";
        shown("mistakes/box-normal-sign/Box.java", test, hint);
        notShown("mistakes/box-zero-direction-misses/Box.java", test, hint);
    }

    @Test
    void theEdgeHintForASwappedEdgeAndTheNormalHintForAWrongNormal() {
        String edge = "edge test written the other way round";
        String normal = "record the normal (b − a) × (c − a)";
        shown("mistakes/triangle-swapped-edge/Triangle.java", "triangle: a ray onto the inside of the triangle", edge);
        notShown("mistakes/triangle-swapped-edge/Triangle.java", "triangle: hit from behind", normal);
        shown("mistakes/triangle-normal-toward-ray/Triangle.java", "triangle: hit from behind", normal);
        notShown("mistakes/triangle-normal-toward-ray/Triangle.java", "triangle: hit from behind", edge);
    }

    @Test
    void theClosedEdgeHintForTheSlidesStrictTest() {
        String hint = "≥ 0, not the lecture's > 0";
        assertTrue(visibleOutput("mistakes/triangle-strict-edges/Triangle.java").contains(hint),
                visibleOutput("mistakes/triangle-strict-edges/Triangle.java"));
        assertFalse(visibleOutput("mistakes/triangle-swapped-edge/Triangle.java").contains(hint),
                visibleOutput("mistakes/triangle-swapped-edge/Triangle.java"));
    }

    @Test
    void theReflectionVectorHintForPhongsRAndTheNDotLHintForNDotL() {
        String test = "phong: v off the normal";
        String reflection = "reflection-vector term";
        String nl = "not n·l";
        shown("mistakes/phong-reflection-vector/BlinnPhong.java", test, reflection);
        notShown("mistakes/phong-reflection-vector/BlinnPhong.java", test, nl);
        shown("mistakes/phong-n-dot-l/BlinnPhong.java", test, nl);
        notShown("mistakes/phong-n-dot-l/BlinnPhong.java", test, reflection);
        // Where n·l and r·v coincide (v = n), the hint names neither alone.
        notShown("mistakes/phong-reflection-vector/BlinnPhong.java", "phong: v = n, l along the surface", nl);
    }

    @Test
    void theSkipHintOnlyForALightThatWasNotSkipped() {
        String test = "lambert: a light in shadow adds nothing";
        String hint = "skip a light when at.visible(light) is false";
        shown("mistakes/lambert-shadow-ignored/Shading.java", test, hint);
        notShown("bugs2/Shading.java", test, hint); // skips blocked lights; adds the ambient term per light
        notShown("mistakes/lambert-shadow-gates-diffuse-only/Shading.java", test, hint);
        shown("mistakes/lambert-shadow-gates-diffuse-only/Shading.java", test, "no highlight either");
    }

    @Test
    void theNDotLHintIsNotShownForAHalvedHalfVector() {
        String test = "phong: v off the normal";
        shown("mistakes/phong-half-vector-halved/BlinnPhong.java", test, "halving v + l");
        notShown("mistakes/phong-half-vector-halved/BlinnPhong.java", test, "not n·l");
        notShown("mistakes/phong-n-dot-l/BlinnPhong.java", test, "halving v + l");
    }

    @Test
    void theZeroComponentHintOnTheSixFacesOnlyWhenTheZeroComponentsAloneBreakIt() {
        String test = "box: each of the 6 faces";
        String hint = "0/0 = NaN";
        notShown("bugs1/Box.java", test, hint); // never swaps t_min and t_max when d < 0
        shown("bugs1/Box.java", test, "swap t_min and t_max");
        // In the same test, for a box that misses every ray with a zero direction component:
        shown("mistakes/box-zero-direction-misses/Box.java", test, hint);
        notShown("mistakes/box-zero-direction-misses/Box.java", test, "swap t_min and t_max");
        assertTrue(visibleOutput("bugs3/Box.java").contains(hint), visibleOutput("bugs3/Box.java")); // no d = 0 case
    }
}
