package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.FileTrees;
import raylab.grade.platform.ClassScale;

/**
 * {@code grade-all} at class scale, each grade-all a process of its own as on a cluster: the
 * shipped Slurm and Kubernetes job files (grader/cluster/) run two shards side by side and the
 * merge step writes the gradebook; {@code kill -9} of grade-all at seeded random moments leaves
 * no grading running and loses or doubles nothing; a student folder locked by another grade-all
 * is left alone. Every gradebook cell is checked against the student's results.json. Graded on
 * the box milestone only (grading is slow).
 */
@ExtendWith(SharedGraderCache.class)
class GradeAllClassScaleTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static final Path ROOT = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    static final List<String> OPTIONS = List.of("--milestone", "box", "--jobs", "2", "--grade-option=--test-timeout=30",
            "--grade-option=--milestone-timeout=300", "--grade-option=--scene-timeout=120", "--grade-option=--heap=256");

    @TempDir
    Path dir;

    /** {@code raylab} as a command line: this JVM's class path. */
    static String raylab() {
        return Path.of(System.getProperty("java.home"), "bin", "java") + " " + JvmOptions.graderLine() + " -cp "
                + System.getProperty("java.class.path") + " raylab.cli.Main";
    }

    /** A class of six: the reference, two realistic bugs, a compile error, an empty folder, a broken zip. */
    private Map<String, Double> classOfSix(Path subs) throws Exception {
        Map<String, Double> expected = new LinkedHashMap<>(); // box points where known exactly; NaN: below 15
        Path ref = GraderTest.submission(dir, "reference");
        Files.createDirectories(subs.resolve("ref"));
        Files.copy(ref.resolve("Box.java"), subs.resolve("ref/Box.java"));
        expected.put("ref", 15.0);
        for (String bug : List.of("bugs3", "bugs4")) {
            FileTrees.copy(GraderTest.submission(dir, bug), subs.resolve(bug));
            expected.put(bug, Double.NaN);
        }
        Files.createDirectories(subs.resolve("compile-error"));
        Files.writeString(subs.resolve("compile-error/Box.java"), Files.readString(ref.resolve("Box.java")).replace("return", "retur n"));
        expected.put("compile-error", 0.0);
        Files.createDirectories(subs.resolve("empty-folder"));
        expected.put("empty-folder", 0.0);
        byte[] junk = new byte[2048];
        new Random(77).nextBytes(junk);
        Files.write(subs.resolve("broken.zip"), junk);
        expected.put("broken", 0.0);
        return expected;
    }

    @Test
    void theSlurmAndKubernetesJobFilesGradeShardsSideBySideAndTheMergeWritesTheGradebook() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("submissions"));
        Map<String, Double> expected = classOfSix(subs);
        Path out = dir.resolve("graded");
        Path cluster = ROOT.resolve("grader/cluster");

        // The Kubernetes Job: an Indexed Job whose pods run grade-shard.sh with SHARDS = completions.
        String job = Files.readString(cluster.resolve("grade-all-job.yaml"));
        assertTrue(job.contains("completionMode: Indexed"), job);
        assertTrue(job.contains("command: [\"/course/grader/cluster/grade-shard.sh\"]"), job);
        assertEquals(yamlValue(job, "completions: (\\d+)"), yamlValue(job, "name: SHARDS\\s+value: \"(\\d+)\""),
                "SHARDS is the Job's completions");
        assertTrue(Files.readString(cluster.resolve("merge-job.yaml")).contains("command: [\"/course/grader/cluster/merge.sh\"]"));

        // Shard 1 as Slurm runs array task 1 of --array=1-2 (a copy of the batch file, from the submit
        // folder); shard 2 as Kubernetes runs the pod of index 1: at the same time, two processes.
        Path spool = dir.resolve("slurm-spool");
        Files.createDirectories(spool);
        Files.copy(cluster.resolve("grade-all.sbatch"), spool.resolve("slurm_script"));
        Map<String, String> common = Map.of("SUBMISSIONS", subs.toString(), "OUT", out.toString(), "RAYLAB", raylab());
        // Each shard's own cache, where the job files put it (RAYLAB_CACHE unset), already built.
        SharedGraderCache.seed(out.resolve(".cache/shard-1"));
        SharedGraderCache.seed(out.resolve(".cache/shard-2"));
        Map<String, String> slurm = new LinkedHashMap<>(common);
        slurm.putAll(Map.of("SLURM_ARRAY_TASK_ID", "1", "SLURM_ARRAY_TASK_MIN", "1", "SLURM_ARRAY_TASK_COUNT", "2",
                "SLURM_SUBMIT_DIR", ROOT.toString()));
        Map<String, String> kube = new LinkedHashMap<>(common);
        kube.putAll(Map.of("JOB_COMPLETION_INDEX", "1", "SHARDS", "2", "RAYLAB_ROOT", ROOT.toString()));
        List<String> slurmCmd = new ArrayList<>(List.of("bash", spool.resolve("slurm_script").toString()));
        slurmCmd.addAll(OPTIONS);
        List<String> kubeCmd = new ArrayList<>(List.of(cluster.resolve("grade-shard.sh").toString()));
        kubeCmd.addAll(OPTIONS);
        Process one = start(slurmCmd, slurm, dir.resolve("shard1.log"));
        Process two = start(kubeCmd, kube, dir.resolve("shard2.log"));
        assertTrue(one.waitFor(30, TimeUnit.MINUTES) && two.waitFor(30, TimeUnit.MINUTES), "the shards ended");
        assertEquals(0, one.exitValue(), () -> "shard 1: " + read(dir.resolve("shard1.log")));
        assertEquals(0, two.exitValue(), () -> "shard 2: " + read(dir.resolve("shard2.log")));
        assertTrue(read(dir.resolve("shard1.log")).contains("3 submission(s) in shard 1/2 (of 6)"), read(dir.resolve("shard1.log")));
        assertTrue(read(dir.resolve("shard2.log")).contains("3 submission(s) in shard 2/2 (of 6)"), read(dir.resolve("shard2.log")));

        // Each shard's gradebook holds its own students; together every student once.
        Map<String, String[]> s1 = gradebook(out.resolve("gradebook.shard-1-of-2.csv"));
        Map<String, String[]> s2 = gradebook(out.resolve("gradebook.shard-2-of-2.csv"));
        Set<String> both = new HashSet<>(s1.keySet());
        both.retainAll(s2.keySet());
        assertEquals(Set.of(), both, "no student in two shards");
        Set<String> union = new HashSet<>(s1.keySet());
        union.addAll(s2.keySet());
        assertEquals(expected.keySet(), union, "every student in a shard");

        // The merge step, as Slurm runs merge.sbatch after the array.
        Files.copy(cluster.resolve("merge.sbatch"), spool.resolve("merge_script"));
        Map<String, String> merge = new LinkedHashMap<>(common);
        merge.put("SLURM_SUBMIT_DIR", ROOT.toString());
        Process m = start(List.of("bash", spool.resolve("merge_script").toString(), "--milestone", "box"), merge, dir.resolve("merge.log"));
        assertTrue(m.waitFor(5, TimeUnit.MINUTES));
        assertEquals(0, m.exitValue(), () -> "merge: " + read(dir.resolve("merge.log")));
        Map<String, String[]> rows = checkGradebook(out, expected);
        for (String s : expected.keySet()) {
            assertEquals(List.of((s1.containsKey(s) ? s1 : s2).get(s)), List.of(rows.get(s)), "the merged row of " + s + " is its shard's");
        }

        // A submission no shard finished is not lost silently: its row says so, and the merge fails.
        Files.delete(out.resolve("bugs4").resolve(".raylab-graded"));
        Process again = start(List.of(cluster.resolve("merge.sh").toString(), "--milestone", "box"),
                Map.of("SUBMISSIONS", subs.toString(), "OUT", out.toString(), "RAYLAB", raylab(), "RAYLAB_ROOT", ROOT.toString()),
                dir.resolve("merge2.log"));
        assertTrue(again.waitFor(5, TimeUnit.MINUTES));
        assertEquals(1, again.exitValue(), () -> "merge with a student not graded: " + read(dir.resolve("merge2.log")));
        assertEquals("not graded", gradebook(out.resolve("gradebook.csv")).get("bugs4")[3]);
    }

    @Test
    void killNineAtRandomMomentsLeavesNoGradingRunningAndLosesOrDoublesNothing() throws Exception {
        long seed = Long.getLong("raylab.test.seed", System.nanoTime());
        Random random = new Random(seed);
        String why = "seed " + seed + " (rerun with -Draylab.test.seed=" + seed + ")";
        Path subs = Files.createDirectories(dir.resolve("submissions"));
        Map<String, Double> expected = classOfSix(subs);
        Path out = dir.resolve("graded");
        List<String> cmd = new ArrayList<>(List.of(raylab().split(" ")));
        cmd.addAll(List.of("grade-all", subs.toString(), "--out", out.toString(), "--root", ROOT.toString(),
                "--cache", dir.resolve("cache").toString()));
        cmd.addAll(OPTIONS);
        SharedGraderCache.seed(dir.resolve("cache"));
        int kills = 0;
        for (int round = 0; round < 3; round++) {
            Process p = start(cmd, Map.of(), dir.resolve("run" + round + ".log"));
            long wait = 2_000 + random.nextInt(20_000);
            if (p.waitFor(wait, TimeUnit.MILLISECONDS)) {
                break; // everything graded before the moment drawn
            }
            List<ProcessHandle> below = p.descendants().toList();
            p.destroyForcibly(); // SIGKILL: no shutdown hook, nothing of grade-all's own runs
            p.waitFor();
            kills++;
            for (ProcessHandle h : below) {
                try {
                    h.onExit().get(30, TimeUnit.SECONDS);
                } catch (TimeoutException e) {
                    fail("process " + h.pid() + " (" + h.info().commandLine().orElse("?") + ") still runs 30 s after grade-all"
                            + " was killed at " + wait + " ms: an orphan; " + why);
                }
            }
            // What is marked graded is a whole grading of this very submission.
            for (String s : expected.keySet()) {
                Path marker = out.resolve(s).resolve(".raylab-graded");
                if (Files.isRegularFile(marker)) {
                    assertTrue(Files.isRegularFile(out.resolve(s).resolve("results.json")), s + " marked graded without results; " + why);
                }
            }
        }
        System.out.println("GradeAllClassScaleTest: " + kills + " kill(s), " + why);

        // A folder another grade-all holds is left alone (its row says so), the rest is graded.
        Path locked = out.resolve("ref");
        Files.createDirectories(locked);
        Files.deleteIfExists(locked.resolve(".raylab-graded"));
        try (ClassScale.Lock held = ClassScale.Lock.tryTake(locked.resolve(".raylab-grade-all.lock"))) {
            assertNotNull(held, "the test takes the lock");
            Process p = start(cmd, Map.of(), dir.resolve("locked.log"));
            assertTrue(p.waitFor(30, TimeUnit.MINUTES));
            String log = read(dir.resolve("locked.log"));
            assertEquals(1, p.exitValue(), () -> "a student not graded: " + log + "; " + why);
            assertTrue(log.contains("ref: NOT GRADED: another grade-all is grading it"), log);
            assertFalse(Files.exists(locked.resolve("results.json")) && Files.exists(locked.resolve(".raylab-graded")), why);
            assertFalse(gradebook(out.resolve("gradebook.csv")).get("ref")[3].equals("graded"), why);
        }
        Process p = start(cmd, Map.of(), dir.resolve("last.log"));
        assertTrue(p.waitFor(30, TimeUnit.MINUTES));
        String log = read(dir.resolve("last.log"));
        assertEquals(0, p.exitValue(), () -> log + "; " + why);
        assertTrue(log.contains("5 already graded, 1 to grade"), () -> log + "; " + why);
        checkGradebook(out, expected);
    }

    /** The gradebook: one row per student, graded, each cell its results.json; the known scores. */
    private static Map<String, String[]> checkGradebook(Path out, Map<String, Double> expected) throws IOException {
        List<String> lines = Files.readAllLines(out.resolve("gradebook.csv"));
        assertEquals("student,box,total,status", lines.get(0));
        assertEquals(expected.size() + 1, lines.size(), () -> "one row per student: " + lines);
        Map<String, String[]> rows = gradebook(out.resolve("gradebook.csv"));
        assertEquals(expected.keySet(), rows.keySet());
        for (Map.Entry<String, Double> e : expected.entrySet()) {
            String[] c = rows.get(e.getKey());
            assertEquals("graded", c[3], "status of " + e.getKey());
            JsonNode r = JSON.readTree(out.resolve(e.getKey()).resolve("results.json").toFile());
            double own = 0;
            for (JsonNode t : r.get("tests")) {
                own += t.get("score").asDouble();
            }
            assertEquals(own, Double.parseDouble(c[1]), 0.005, "the box cell of " + e.getKey() + " is its results.json");
            assertEquals(r.get("score").asDouble(), Double.parseDouble(c[2]), 0.005, "the total of " + e.getKey());
            if (e.getValue().isNaN()) {
                assertTrue(Double.parseDouble(c[1]) < 15, e.getKey() + " loses points: " + c[1]);
            } else {
                assertEquals(e.getValue(), Double.parseDouble(c[1]), 0.005, e.getKey());
            }
        }
        return rows;
    }

    private static Map<String, String[]> gradebook(Path csv) throws IOException {
        Map<String, String[]> rows = new LinkedHashMap<>();
        List<String> lines = Files.readAllLines(csv);
        for (String l : lines.subList(1, lines.size())) {
            String[] c = l.split(",", -1);
            assertFalse(rows.containsKey(c[0]), "a student twice in " + csv + ": " + c[0]);
            rows.put(c[0], c);
        }
        return rows;
    }

    private static String yamlValue(String yaml, String regex) {
        Matcher m = Pattern.compile(regex).matcher(yaml);
        assertTrue(m.find(), regex + " in the job file");
        return m.group(1);
    }

    private static Process start(List<String> cmd, Map<String, String> env, Path log) throws IOException {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).redirectInput(ProcessBuilder.Redirect.PIPE);
        pb.environment().keySet().removeIf(k -> k.startsWith("SLURM_") || k.equals("JOB_COMPLETION_INDEX"));
        pb.environment().putAll(env);
        return pb.start();
    }

    private static String read(Path p) {
        try {
            return Files.readString(p, StandardCharsets.UTF_8);
        } catch (IOException e) {
            return "(" + e + ")";
        }
    }
}
