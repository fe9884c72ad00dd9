package raylab.grade.platform;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.cli.OptionalCommand;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.grade.GradingStatus;

/**
 * {@code raylab grade-all SUBMISSIONS_DIR --out DIR}: grades every submission of a class. Each
 * entry of SUBMISSIONS_DIR (a folder or a zip; the student is its name without {@code .zip}) is
 * graded by {@code raylab grade} in a JVM of its own, so nothing one submission does (or does to
 * the grader) touches another; at most {@code --jobs} at a time. Each student's results go to
 * {@code DIR/STUDENT/} with a marker holding a digest of the submission, so a second run grades
 * only what is new, changed or failed (resume). Then {@code DIR/gradebook.csv}: one row per
 * student, one column per milestone, the total and a status.
 *
 * <p>One command: grading a class, its resume markers and its gradebook, which read the same
 * per-student folders.
 */
@Command(name = "grade-all", mixinStandardHelpOptions = true,
        description = {"Grade every submission in a folder (instructors): each entry (a folder or a zip) is one student.",
            "Writes DIR/STUDENT/ (results.json, report.html, ...) and DIR/gradebook.csv; run it again to resume.",
            "Details: docs/instructors.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every submission graded", "1:some could not be graded (their rows say so)", "2:bad option"})
public final class GradeAllCommand implements Callable<Integer>, OptionalCommand {
    /** The marker of a finished grading: the submission's digest. */
    static final String DONE = ".raylab-graded";
    /** Held by the grade-all that grades the student (released by the kernel when it ends, however). */
    static final String LOCK = ".raylab-grade-all.lock";

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SUBMISSIONS_DIR", description = "One folder or zip per student.")
    Path submissions;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Where to write the results and the gradebook.")
    Path out;

    @Option(names = "--jobs", paramLabel = "N",
            description = "Submissions graded at the same time (default: from the cores and the memory, ${DEFAULT-VALUE} here).")
    int jobs = ClassScale.defaultJobs();

    @Option(names = "--shard", paramLabel = "K/N", converter = ClassScale.ShardConverter.class,
            description = {"Grade only shard K of N (the sorted submissions whose position is K modulo N), for a Slurm",
                "job array or a Kubernetes Indexed Job; writes DIR/gradebook.shard-K-of-N.csv. Then --merge."})
    ClassScale.Shard shard;

    @Option(names = "--merge", description = {"Grade nothing: write DIR/gradebook.csv from every student's results",
        "(after the shards); exit 1 if any submission is not graded."})
    boolean merge;

    @Option(names = "--milestone", paramLabel = "M", description = "Grade only these milestones (repeatable).")
    List<String> milestones = new ArrayList<>();

    @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project root (default: current directory).")
    Path root = Path.of(".");

    @Option(names = "--cache", paramLabel = "DIR", description = "Cache of built grader classes (default: ROOT/target/grader-cache).")
    Path cache;

    @Option(names = "--timeout", paramLabel = "S", description = "Time limit of one submission's grading, seconds (default: ${DEFAULT-VALUE}).")
    int timeout = 1800;

    @Option(names = "--again", description = "Grade every submission again, even those already graded.")
    boolean again;

    @Option(names = "--grade-option", paramLabel = "OPT", hidden = true,
            description = "An option passed on to each `raylab grade` (repeatable; for tests).")
    List<String> gradeOptions = new ArrayList<>();

    /** One student's outcome. */
    record Row(String student, Map<String, Double> milestones, double total, String status) {
    }

    @Override
    public Integer call() throws Exception {
        PrintWriter log = spec.commandLine().getErr();
        if (!Files.isDirectory(submissions)) {
            throw UserError.badInput(submissions + ": not a folder (the folder of submissions)");
        }
        if (jobs < 1) {
            throw UserError.badInput("--jobs must be at least 1, got " + jobs);
        }
        if (merge && shard != null) {
            throw UserError.badInput("--merge and --shard: the merge step comes after every shard, without --shard");
        }
        Path r = root.toAbsolutePath().normalize();
        Assignments all;
        try {
            all = Assignments.load(r);
        } catch (IOException e) {
            throw UserError.badInput(e.getMessage());
        }
        List<String> ids = new ArrayList<>();
        for (Assignment a : all.all()) {
            if (milestones.isEmpty() || milestones.contains(a.id())) {
                ids.add(a.id());
            }
        }
        for (String m : milestones) {
            if (all.byId(m).isEmpty()) {
                throw UserError.badInput("unknown milestone '" + m + "': valid ids are " + String.join(", ", all.ids()));
            }
        }
        Path o = out.toAbsolutePath().normalize();
        Files.createDirectories(o);
        Map<String, Path> entries = entries(submissions);
        if (entries.isEmpty()) {
            throw UserError.badInput(submissions + ": no submissions (folders or .zip files) in it");
        }
        Map<String, Path> mine = shard == null ? entries : shard.of(entries);
        List<String> todo = new ArrayList<>();
        for (Map.Entry<String, Path> e : mine.entrySet()) {
            if (!merge && (again || !done(o.resolve(e.getKey()), e.getValue()))) {
                todo.add(e.getKey());
            }
        }
        if (merge) {
            log.println("raylab grade-all --merge: " + entries.size() + " submission(s), nothing graded");
        } else {
            log.println("raylab grade-all: " + mine.size() + " submission(s)" + (shard == null ? "" : " in shard " + shard
                    + " (of " + entries.size() + ")") + ", " + (mine.size() - todo.size()) + " already graded, " + todo.size()
                    + " to grade, " + jobs + " at a time");
        }
        log.flush();
        AtomicInteger failures = new AtomicInteger();
        if (!todo.isEmpty()) {
            // The bar (with the remaining time) only on a terminal; in a log one line per submission,
            // each with the time left, from the mean time per submission so far.
            ProgressBar bar = System.console() == null ? null : new ProgressBarBuilder().setTaskName("grading")
                    .setInitialMax(todo.size()).setUnit(" submissions", 1)
                    .setConsumer(new ConsoleProgressBarConsumer(System.err)).setUpdateIntervalMillis(1000)
                    .continuousUpdate().build();
            Progress progress = new Progress(todo.size(), bar, System.nanoTime());
            try {
                // The first grading alone: it builds the grader cache the others then share.
                grade(todo.get(0), entries.get(todo.get(0)), o, r, failures, log, progress);
                ExecutorService pool = Executors.newFixedThreadPool(jobs);
                try {
                    List<Future<?>> fs = new ArrayList<>();
                    for (String s : todo.subList(1, todo.size())) {
                        fs.add(pool.submit(() -> {
                            grade(s, entries.get(s), o, r, failures, log, progress);
                            return null;
                        }));
                    }
                    for (Future<?> f : fs) {
                        f.get();
                    }
                } finally {
                    pool.shutdownNow();
                }
            } finally {
                if (bar != null) {
                    bar.close();
                }
            }
        }
        List<Row> rows = new ArrayList<>();
        for (String s : mine.keySet()) {
            rows.add(row(s, o.resolve(s), ids));
        }
        Path csv = o.resolve(shard == null ? "gradebook.csv" : "gradebook.shard-" + shard.k() + "-of-" + shard.n() + ".csv");
        writeAtomically(csv, csv(rows, ids));
        long bad = rows.stream().filter(x -> !x.status().equals("graded")).count();
        spec.commandLine().getOut().println("wrote " + csv + ": " + rows.size() + " student(s)"
                + (bad > 0 ? ", " + bad + " not graded (see the status column and DIR/STUDENT/grade.log; run the same"
                        + " command again to grade them again)" : ""));
        return bad > 0 || failures.get() > 0 ? 1 : 0;
    }

    /** Submissions by student name, sorted: folders and .zip files, not hidden ones. */
    static Map<String, Path> entries(Path dir) throws IOException {
        Map<String, Path> m = new java.util.TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String name = p.getFileName().toString();
                if (name.startsWith(".")) {
                    continue;
                }
                boolean zip = name.toLowerCase(Locale.ROOT).endsWith(".zip") && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS);
                if (!zip && !Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                String student = safe(zip ? name.substring(0, name.length() - 4) : name);
                m.putIfAbsent(student, p);
            }
        }
        return m;
    }

    /** A folder name for the student: letters, digits, '.', '_', '-', '@'; anything else '_'. */
    static String safe(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            b.append(Character.isLetterOrDigit(c) || c == '.' || c == '_' || c == '-' || c == '@' ? c : '_');
        }
        String t = b.toString();
        return t.isEmpty() || t.startsWith(".") ? "_" + t : t;
    }

    private static boolean done(Path dir, Path submission) throws IOException {
        Path marker = dir.resolve(DONE);
        return Files.isRegularFile(marker) && Files.isRegularFile(dir.resolve("results.json"))
                && Files.readString(marker, StandardCharsets.UTF_8).strip().equals(digest(submission));
    }

    /** A digest of the submission: every regular file's relative path and bytes (links not followed). */
    static String digest(Path submission) throws IOException {
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
        if (Files.isRegularFile(submission, LinkOption.NOFOLLOW_LINKS)) {
            try (InputStream in = Files.newInputStream(submission)) {
                md.update(in.readAllBytes());
            }
        } else {
            try (Stream<Path> s = Files.walk(submission)) {
                for (Path p : (Iterable<Path>) s.sorted()::iterator) {
                    if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                        md.update(submission.relativize(p).toString().getBytes(StandardCharsets.UTF_8));
                        md.update((byte) 0);
                        md.update(Files.readAllBytes(p));
                    }
                }
            }
        }
        return HexFormat.of().formatHex(md.digest());
    }

    /** Submissions done, and the time left from the mean wall time per submission so far. */
    static final class Progress {
        private final int total;
        private final ProgressBar bar;
        private final long t0;
        private int done;

        Progress(int total, ProgressBar bar, long t0) {
            this.total = total;
            this.bar = bar;
            this.t0 = t0;
        }

        synchronized String step() {
            done++;
            if (bar != null) {
                bar.step();
            }
            // Wall time per submission so far (with the jobs running side by side) times those left.
            double perEach = (System.nanoTime() - t0) / 1e9 / done;
            long left = Math.round(perEach * (total - done));
            return "[" + done + "/" + total + (done < total ? ", about " + (left >= 120 ? left / 60 + " min" : left + " s")
                    + " left" : "") + "]";
        }
    }

    /** Grades one submission in a JVM of its own; never throws. */
    private void grade(String student, Path submission, Path o, Path r, AtomicInteger failures, PrintWriter log,
            Progress progress) {
        Path dir = o.resolve(student);
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            failures.incrementAndGet();
            report(log, progress, student, "NOT GRADED: " + e);
            return;
        }
        // One grade-all at a time per student folder: a second one (a rerun while the first still
        // runs, two shards given the same submissions) leaves it alone and says so.
        try (ClassScale.Lock lock = ClassScale.Lock.tryTake(dir.resolve(LOCK))) {
            if (lock == null) {
                failures.incrementAndGet();
                report(log, progress, student, "NOT GRADED: another grade-all is grading it (" + dir.resolve(LOCK) + " is locked)");
                return;
            }
            gradeLocked(student, submission, dir, r, failures, log, progress);
        } catch (IOException e) {
            failures.incrementAndGet();
            report(log, progress, student, "NOT GRADED: " + e);
        }
    }

    private void gradeLocked(String student, Path submission, Path dir, Path r, AtomicInteger failures, PrintWriter log,
            Progress progress) {
        try {
            Files.deleteIfExists(dir.resolve(DONE));
            // What an earlier (stopped) grading left is never taken for this one's result.
            Files.deleteIfExists(dir.resolve("results.json"));
            String digest = digest(submission);
            List<String> cmd = new ArrayList<>(List.of(JavaBuild.javaExecutable()));
            cmd.addAll(raylab.grade.JvmOptions.GRADER);
            cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main", "grade",
                    submission.toAbsolutePath().toString(), "--out", dir.toString(), "--root", r.toString(), "--quiet",
                    // It ends when this JVM does (its standard input, a pipe from here, closes), and
                    // it holds a lock of its own on the folder while it writes there.
                    "--die-with-parent", "--lock", dir.resolve(ClassScale.GRADING_LOCK).toString()));
            if (cache != null) {
                cmd.addAll(List.of("--cache", cache.toAbsolutePath().toString()));
            }
            for (String m : milestones) {
                cmd.addAll(List.of("--milestone", m));
            }
            cmd.addAll(gradeOptions);
            Path logFile = dir.resolve("grade.log");
            Process p = new ProcessBuilder(cmd).directory(r.toFile()).redirectErrorStream(true)
                    .redirectOutput(logFile.toFile()).redirectInput(ProcessBuilder.Redirect.PIPE).start();
            if (!p.waitFor(timeout, TimeUnit.SECONDS)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                p.waitFor(30, TimeUnit.SECONDS);
                Files.writeString(dir.resolve("error.txt"), "the grading took longer than " + timeout + " s\n");
                failures.incrementAndGet();
                report(log, progress, student, "NOT GRADED: longer than " + timeout + " s");
                return;
            }
            int status = p.exitValue();
            p.getOutputStream().close();
            if (Files.isRegularFile(dir.resolve("results.json")) && status != 1) {
                // 0: graded; 2: the submission was unreadable or absent (results.json says so, score 0).
                Files.deleteIfExists(dir.resolve("error.txt"));
                writeAtomically(dir.resolve(DONE), digest + "\n");
                report(log, progress, student, score(dir.resolve("results.json")));
            } else {
                Files.writeString(dir.resolve("error.txt"), "raylab grade ended with status " + status + "; see grade.log\n");
                failures.incrementAndGet();
                report(log, progress, student, gradingFailed(dir.resolve("results.json"))
                        ? "NOT GRADED: the grading failed on the grader's side, no points decided (status " + status
                                + "), see " + logFile
                        : "NOT GRADED: the grader failed (status " + status + "), see " + logFile);
            }
        } catch (Exception | Error e) {
            failures.incrementAndGet();
            try {
                Files.writeString(dir.resolve("error.txt"), String.valueOf(e) + "\n");
            } catch (IOException ignored) {
                // the row says "failed" anyway
            }
            report(log, progress, student, "NOT GRADED: " + e);
        }
    }

    private static void report(PrintWriter log, Progress progress, String student, String what) {
        String step = progress.step();
        synchronized (log) {
            log.println((progress.bar == null ? "" : "\r") + step + " " + student + ": " + what);
            log.flush();
        }
    }

    private static String score(Path results) {
        try {
            JsonNode n = new ObjectMapper().readTree(results.toFile());
            return "score " + fmt(n.get("score").asDouble());
        } catch (IOException | RuntimeException e) {
            return "graded";
        }
    }

    /** The student's row from DIR/STUDENT/results.json (Gradescope format, tests tagged with their milestone). */
    static Row row(String student, Path dir, List<String> ids) {
        Map<String, Double> per = new LinkedHashMap<>();
        if (!Files.isRegularFile(dir.resolve(DONE)) || !Files.isRegularFile(dir.resolve("results.json"))) {
            // Not finished (the next run grades the student again): a grading that failed on the
            // grader's side wrote results.json to say so, with no score; anything else is "failed".
            String status = !Files.isRegularFile(dir.resolve("error.txt")) ? "not graded"
                    : gradingFailed(dir.resolve("results.json")) ? GradingStatus.GRADING_FAILED.label() : "failed";
            return new Row(student, per, 0, status);
        }
        try {
            JsonNode n = new ObjectMapper().readTree(dir.resolve("results.json").toFile());
            for (String id : ids) {
                per.put(id, 0.0);
            }
            for (JsonNode t : n.get("tests")) {
                String m = t.get("tags").get(0).asText();
                if (per.containsKey(m)) {
                    per.put(m, per.get(m) + t.get("score").asDouble());
                }
            }
            double total = 0;
            for (Map.Entry<String, Double> e : per.entrySet()) {
                e.setValue(Math.round(e.getValue() * 100) / 100.0);
                total += e.getValue();
            }
            // A grading that failed on the grader's side decided nothing: its row says so.
            return new Row(student, per, Math.round(total * 100) / 100.0, GradingStatus.ofGradescope(n).label());
        } catch (IOException | RuntimeException e) {
            return new Row(student, Map.of(), 0, "failed");
        }
    }

    /** Whether this results.json says that its grading failed on the grader's side ({@link GradingStatus#ofGradescope}). */
    private static boolean gradingFailed(Path results) {
        try {
            return Files.isRegularFile(results)
                    && GradingStatus.ofGradescope(new ObjectMapper().readTree(results.toFile())) == GradingStatus.GRADING_FAILED;
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    static String csv(List<Row> rows, List<String> ids) {
        StringBuilder b = new StringBuilder("student");
        ids.forEach(i -> b.append(',').append(i));
        b.append(",total,status\n");
        for (Row r : rows) {
            b.append(cell(r.student()));
            for (String i : ids) {
                b.append(',').append(r.milestones().containsKey(i) ? fmt(r.milestones().get(i)) : "");
            }
            b.append(',').append(r.status().equals("graded") ? fmt(r.total()) : "").append(',').append(r.status()).append('\n');
        }
        return b.toString();
    }

    private static String cell(String s) {
        // Student names are made safe (no comma or quote); a leading = + - @ would be a spreadsheet formula.
        return s.matches("^[=+\\-@].*") ? "'" + s : s;
    }

    static String fmt(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        return s.endsWith(".00") ? s.substring(0, s.length() - 3) : s;
    }

    static void writeAtomically(Path target, String text) throws IOException {
        Path tmp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".tmp");
        try {
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
