package raylab.course;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

/**
 * Classroom 50's {@code result.json} ({@code "schema": "classroom50/result/v1"}) from what
 * {@code raylab check} ran in the student's checkout: the visible tests, visible data cases and
 * scenes, nothing hidden (the hidden parts are never in the student's repository, nor in the
 * autograder Classroom 50 runs there, which is public). Classroom 50 wants integer scores: each
 * test's {@code score} and {@code max-score} are in hundredths of a point (a 0.36-point test is
 * 36), and the exact points are beside them as {@code points} and {@code max-points}. A milestone
 * whose files will not compile at the grader (its files use what only the student's copy of the
 * framework, or the student's file of another milestone, has) scores 0 here as it will there, each
 * item with the sentence that says why: the checkout's own build passing is not the grade.
 */
public final class Classroom50Result {
    public static final String SCHEMA = "classroom50/result/v1";

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private Classroom50Result() {
    }

    /**
     * The result for these outcomes, with identity fields from {@code env} and the submission
     * instant; the milestones of {@code wontCompile} (id to the sentences of {@code raylab check}'s
     * "WILL NOT COMPILE AT THE GRADER" lines) score 0.
     */
    public static Map<String, Object> of(List<MilestoneCheck.Outcome> outcomes, Map<String, List<String>> wontCompile,
            Map<String, String> env, Instant when) {
        List<Map<String, Object>> tests = new ArrayList<>();
        long score = 0;
        long max = 0;
        for (MilestoneCheck.Outcome o : outcomes) {
            String id = o.assignment().id();
            List<MilestoneCheck.Outcome.Row> rows = o.rows();
            if (rows.isEmpty() && !o.problem().isEmpty()) {
                Map<String, Object> t = new LinkedHashMap<>();
                t.put("test-name", id + ": " + "could not run");
                t.put("passed", false);
                t.put("score", 0);
                t.put("max-score", 0);
                t.put("milestone", id);
                t.put("message", o.problem());
                tests.add(t);
            }
            List<String> why = wontCompile.getOrDefault(id, List.of());
            String atGrader = why.isEmpty() ? "" : "will not compile at the grader: " + String.join("; and ", why);
            for (MilestoneCheck.Outcome.Row r : rows) {
                GradingPlan.Item i = r.item();
                boolean passed = r.passed() && why.isEmpty();
                long earned = passed ? i.cents() : 0;
                Map<String, Object> t = new LinkedHashMap<>();
                String kind = switch (i.kind()) {
                    case TEST -> "test";
                    case CASE -> "data case";
                    case SCENE -> "scene";
                };
                t.put("test-name", id + ": " + (i.kind() == GradingPlan.Kind.CASE ? "data case " : "") + i.name());
                t.put("passed", passed);
                t.put("score", earned);
                t.put("max-score", i.cents());
                t.put("milestone", id);
                t.put("kind", kind);
                t.put("points", GradingPlan.points(earned));
                t.put("max-points", GradingPlan.points(i.cents()));
                t.put("message", passed ? "" : oneParagraph(atGrader.isEmpty() ? r.message() : atGrader
                        + (r.passed() ? " (it passes in this checkout, whose build uses your own files)" : "")));
                tests.add(t);
                score += earned;
                max += i.cents();
            }
        }
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("schema", SCHEMA);
        root.put("classroom", env.getOrDefault("CLASSROOM", ""));
        root.put("assignment", env.getOrDefault("ASSIGNMENT", ""));
        root.put("submission", env.getOrDefault("SUBMISSION_TAG", ""));
        String commit = env.getOrDefault("COMMIT_URL", "");
        root.put("commit", commit);
        root.put("release", env.getOrDefault("RELEASE_URL", ""));
        String review = env.getOrDefault("REVIEW_URL", "");
        root.put("review", review.isEmpty() ? commit : review);
        root.put("datetime", when.truncatedTo(ChronoUnit.SECONDS).toString());
        root.put("graded_at", Instant.now().truncatedTo(ChronoUnit.SECONDS).toString());
        root.put("score", score);
        root.put("max-score", max);
        root.put("tests", tests);
        return root;
    }

    /** Writes the result to {@code file} (a temporary file beside it, renamed over it). */
    public static void write(Path file, List<MilestoneCheck.Outcome> outcomes, Map<String, List<String>> wontCompile,
            Map<String, String> env, Path checkout) throws IOException {
        String text = JSON.writeValueAsString(of(outcomes, wontCompile, env, commitInstant(checkout)));
        Path abs = file.toAbsolutePath();
        Path tmp = Files.createTempFile(abs.getParent(), "." + abs.getFileName(), ".tmp");
        try {
            Files.writeString(tmp, text + "\n", StandardCharsets.UTF_8);
            Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /**
     * The submission instant Classroom 50 asks for: the committer date of the checkout's HEAD
     * (the same on every regrade), or now when there is no git history.
     */
    static Instant commitInstant(Path checkout) {
        try {
            Process p = new ProcessBuilder("git", "log", "-1", "--format=%ct").directory(checkout.toFile())
                    .redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            if (p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0 && out.matches("\\d+")) {
                return Instant.ofEpochSecond(Long.parseLong(out));
            }
        } catch (IOException e) {
            // no git: now
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return Instant.now();
    }

    private static String oneParagraph(String s) {
        String t = s == null ? "" : s.strip();
        return t.length() <= 2000 ? t : t.substring(0, 1997) + "...";
    }
}
