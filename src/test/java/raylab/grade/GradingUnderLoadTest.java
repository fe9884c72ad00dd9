package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Load is never the student's fault: correct submissions (the reference and a correct
 * alternative) graded beside CPU hogs (4 busy processes per core) and with the grader's own
 * answers slowed down ({@code -Draylab.boundary.slowGrader}) score exactly what they score on a
 * quiet machine with the same seed, test by test, with the default time limits, and the grading
 * does not fail. Each grading is a {@code raylab grade} process of its own, on the box milestone,
 * with a grader cache of its own (a copy of the shared build); the two submissions are graded side by side, first
 * quietly, then beside one set of hogs.
 */
class GradingUnderLoadTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static final Path ROOT = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();

    @TempDir
    Path dir;

    @Test
    void correctCodeScoresTheSameBesideCpuHogsAndASlowGrader() throws Exception {
        Map<String, Path> subs = new LinkedHashMap<>();
        subs.put("reference", GraderTest.submission(dir, "reference"));
        subs.put("alternatives2", GraderTest.submission(dir, "alternatives2"));
        // The grader's cache ready here (a copy of the shared build), not built by each grading.
        SharedGraderCache.seed(dir.resolve("cache"));
        // The quiet gradings side by side (one core each), then the loaded ones side by side beside
        // the same hogs: each loaded grading has the hogs' load and the other grading's besides.
        Map<String, Map<String, Double>> quiet = gradeAll(subs, "quiet-", Map.of());
        int hogs = 4 * Runtime.getRuntime().availableProcessors();
        List<Process> busy = new ArrayList<>();
        Map<String, Map<String, Double>> loaded;
        long t0 = System.nanoTime();
        try {
            for (int i = 0; i < hogs; i++) {
                busy.add(new ProcessBuilder("sh", "-c", "while :; do :; done").start());
            }
            loaded = gradeAll(subs, "loaded-", Map.of("RAYLAB_TRUSTED_JVM_OPTS", "-Draylab.boundary.slowGrader=1"));
        } finally {
            for (Process b : busy) {
                b.destroyForcibly();
            }
        }
        System.out.printf("GradingUnderLoadTest: %s graded side by side in %.0f s beside %d busy processes%n",
                subs.keySet(), (System.nanoTime() - t0) / 1e9, hogs);
        for (String sub : subs.keySet()) {
            assertEquals(quiet.get(sub), loaded.get(sub), sub + ": every test and scene scores as on a quiet machine");
        }
    }

    /** Each submission graded ({@link #grade}), all at the same time: their scores by submission. */
    private Map<String, Map<String, Double>> gradeAll(Map<String, Path> subs, String prefix, Map<String, String> env)
            throws Exception {
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(subs.size());
        try {
            Map<String, java.util.concurrent.Future<JsonNode>> runs = new LinkedHashMap<>();
            for (Map.Entry<String, Path> e : subs.entrySet()) {
                runs.put(e.getKey(), pool.submit(() -> grade(e.getValue(), prefix + e.getKey(), env)));
            }
            Map<String, Map<String, Double>> out = new LinkedHashMap<>();
            for (Map.Entry<String, java.util.concurrent.Future<JsonNode>> r : runs.entrySet()) {
                try {
                    out.put(r.getKey(), scores(r.getValue().get()));
                } catch (java.util.concurrent.ExecutionException x) {
                    // An assertion or error inside the grading, rethrown as it was.
                    if (x.getCause() instanceof Exception ex) {
                        throw ex;
                    }
                    throw (Error) x.getCause();
                }
            }
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /** Each test's and scene's score by name, and the status. */
    private static Map<String, Double> scores(JsonNode results) {
        Map<String, Double> m = new LinkedHashMap<>();
        for (JsonNode t : results.get("tests")) {
            m.put(t.get("name").asText(), t.get("score").asDouble());
        }
        m.put("status: " + GradingStatus.ofGradescope(results).label(), 0.0);
        m.put("total", results.get("score").asDouble());
        return m;
    }

    /** {@code raylab grade} in a process of its own with the default time limits, seed 11. */
    private JsonNode grade(Path sub, String name, Map<String, String> env) throws IOException, InterruptedException {
        Path out = dir.resolve(name);
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JvmOptions.GRADER);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main", "grade", sub.toString(),
                "--out", out.toString(), "--root", ROOT.toString(), "--quiet", "--milestone", "box", "--seed", "11",
                "--cache", dir.resolve("cache").toString()));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(name + ".log").toFile());
        pb.environment().putAll(env);
        Process p = pb.start();
        if (!p.waitFor(60, TimeUnit.MINUTES)) {
            p.destroyForcibly();
        }
        assertEquals(0, p.exitValue(), () -> name + ": " + read(dir.resolve(name + ".log")));
        return JSON.readTree(out.resolve("results.json").toFile());
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            return "(" + e + ")";
        }
    }
}
