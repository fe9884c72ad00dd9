package raylab.course.release;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.cli.Main;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.render.PngFiles;
import raylab.scene.SceneLoader;

/**
 * {@code raylab assignment add-scene|add-case}: grows a milestone in one command (instructors;
 * the starter leaves this class out). Each command changes {@code assignment.json} (the item and
 * the milestone's total), rewrites the handout's grading table from it, and shows what students
 * will see; every file is written to a temporary name and moved, and nothing is changed when a
 * step fails.
 */
@Command(name = "assignment", mixinStandardHelpOptions = true,
        description = {"Add a graded scene or data cases to a milestone (instructors).",
            "Updates assignment.json, the milestone's points and its handout's grading table. See docs/instructors.md."},
        subcommands = {AssignmentCommand.AddScene.class, AssignmentCommand.AddCase.class})
public final class AssignmentCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getOut());
        return 2;
    }

    /** Options both subcommands share. */
    abstract static class Base {
        @Spec
        CommandSpec spec;

        @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project (default: the current folder).")
        Path root = Path.of("");

        Path project() {
            return root.toAbsolutePath().normalize();
        }

        Assignment milestone(Assignments all, String id) {
            return all.byId(id).orElseThrow(() -> UserError.badInput("unknown milestone '" + id + "': valid ids are "
                    + String.join(", ", all.ids())));
        }

        Assignments load() {
            if (!Files.isRegularFile(project().resolve(ReleaseSpec.FILE))) {
                throw UserError.badInput(project() + ": not an instructor tree (no " + ReleaseSpec.FILE + ")");
            }
            try {
                return Assignments.load(project());
            } catch (IOException e) {
                throw UserError.badInput(e.getMessage());
            }
        }

        /**
         * Writes the new assignment.json, checks that the milestones still load, rewrites the
         * handout, and prints what students will see; restores everything if the check fails.
         */
        void commit(Assignment a, String newJson, Map<Path, byte[]> extra, PrintWriter out) throws IOException {
            Path root = project();
            Path json = root.resolve(a.folder()).resolve("assignment.json");
            Path readme = root.resolve(a.folder()).resolve("README.md");
            Map<Path, byte[]> old = new LinkedHashMap<>();
            for (Path p : concat(List.of(json, readme), extra.keySet())) {
                old.put(p, Files.exists(p) ? Files.readAllBytes(p) : null);
            }
            try {
                for (Map.Entry<Path, byte[]> e : extra.entrySet()) {
                    write(e.getKey(), e.getValue());
                }
                write(json, newJson.getBytes(StandardCharsets.UTF_8));
                Assignment updated = Assignments.load(root).byId(a.id()).orElseThrow();
                GradingPlan.Plan plan = GradingPlan.of(root, updated);
                if (Files.isRegularFile(readme)) {
                    String text = Files.readString(readme, StandardCharsets.UTF_8);
                    write(readme, HandoutTable.update(text, plan).getBytes(StandardCharsets.UTF_8));
                }
                out.println("updated " + root.relativize(json) + " (" + a.points() + " -> " + updated.points()
                        + " points) and the grading table of " + root.relativize(readme));
                out.println();
                out.println("The handout's grading table now reads:");
                out.println(HandoutTable.table(plan));
                out.println();
                out.println("What ./raylab check " + a.id() + " lists for students (before they pass anything):");
                for (GradingPlan.Item i : plan.visible()) {
                    if (i.kind() != GradingPlan.Kind.TEST) {
                        out.printf("  %s 0/%-9s %s%n", i.kind() == GradingPlan.Kind.SCENE ? "DIFFERS" : "FAIL   ",
                                GradingPlan.points(i.cents()), i.kind() == GradingPlan.Kind.SCENE
                                        ? i.name() + " (tolerance " + GradingPlan.percent(i.tolerance()) + ")"
                                        : "data case \"" + i.name() + "\"");
                    }
                }
                out.println("  visible total: 0 / " + GradingPlan.points(plan.visibleCents()) + " points");
                if (!plan.hiddenLine().isEmpty()) {
                    out.println("  " + plan.hiddenLine());
                }
                out.println("./raylab grade picks it up from assignment.json; ./raylab release writes it into the starter.");
            } catch (IOException | RuntimeException e) {
                for (Map.Entry<Path, byte[]> o : old.entrySet()) {
                    if (o.getValue() == null) {
                        Files.deleteIfExists(o.getKey());
                    } else {
                        write(o.getKey(), o.getValue());
                    }
                }
                throw new UserError("nothing was changed: " + e.getMessage(), 2);
            }
        }
    }

    /** {@code raylab assignment add-scene MILESTONE SCENE.json --points N [--tolerance T]}. */
    @Command(name = "add-scene", mixinStandardHelpOptions = true,
            description = {"Render a scene's reference image and grade it in a milestone.",
                "The scene is copied into scenes/ if it is elsewhere; the reference goes to scenes/reference/NAME.png."})
    public static final class AddScene extends Base implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "MILESTONE", description = "The milestone id (sphere, box, ...).")
        String milestoneId;

        @Parameters(index = "1", paramLabel = "SCENE.json", description = "The scene file.")
        Path scene;

        @Option(names = "--points", required = true, paramLabel = "N", description = "Points for a match (whole, >= 1).")
        int points;

        @Option(names = "--tolerance", paramLabel = "T",
                description = "Fraction of pixels allowed to differ by more than 2/255 (default: ${DEFAULT-VALUE}).")
        double tolerance = 0.002;

        @Override
        public Integer call() throws Exception {
            PrintWriter out = spec.commandLine().getOut();
            if (points < 1) {
                throw UserError.badInput("--points must be at least 1, got " + points);
            }
            if (!(tolerance >= 0 && tolerance < 1)) {
                throw UserError.badInput("--tolerance must be a fraction in [0, 1), got " + tolerance);
            }
            Assignments all = load();
            Assignment a = milestone(all, milestoneId);
            Path root = project();
            if (!Files.isRegularFile(scene)) {
                throw UserError.badInput(scene + ": no such scene file");
            }
            SceneLoader.load(scene); // a malformed scene is one line and exit 2, before anything changes
            String name = scene.getFileName().toString();
            if (!name.endsWith(".json")) {
                throw UserError.badInput(scene + ": a scene file ends in .json");
            }
            Path inScenes = root.resolve("scenes").resolve(name);
            boolean copy = !inScenes.toAbsolutePath().normalize().equals(scene.toAbsolutePath().normalize());
            if (copy && Files.exists(inScenes)) {
                throw UserError.badInput(root.relativize(inScenes) + " exists already and is another file: rename " + scene);
            }
            String sceneRel = "scenes/" + name;
            String refRel = "scenes/reference/" + name.replaceFirst("\\.json$", ".png");
            for (Assignment o : all.all()) {
                for (Assignment.GradedScene g : o.scenes()) {
                    if (g.scene().equals(sceneRel)) {
                        throw UserError.badInput(sceneRel + " is graded already, in milestone " + o.id());
                    }
                }
            }
            // The reference, rendered with the reference solution (this tree's code), into a temporary file.
            Path tmp = Files.createTempFile("raylab-reference", ".png");
            try {
                StringWriter err = new StringWriter();
                int status = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err), "render", scene.toString(),
                        "-o", tmp.toString(), "--quiet");
                if (status != 0) {
                    throw new UserError("the reference render failed, nothing was changed: " + err.toString().strip(), 1);
                }
                byte[] png = Files.readAllBytes(tmp);
                var image = PngFiles.read(tmp);
                Map<Path, byte[]> extra = new LinkedHashMap<>();
                if (copy) {
                    extra.put(inScenes, Files.readAllBytes(scene));
                }
                extra.put(root.resolve(refRel), png);
                String entry = String.format(Locale.ROOT,
                        "{\"scene\": \"%s\", \"reference\": \"%s\", \"points\": %d, \"tolerance\": %s}", sceneRel, refRel,
                        points, BigDecimalText.of(tolerance));
                String json = Files.readString(root.resolve(a.folder()).resolve("assignment.json"), StandardCharsets.UTF_8);
                String updated = withTotal(addToArray(json, "scenes", entry), a.points() + points);
                out.println("rendered the reference " + refRel + " (" + image.getWidth() + "x" + image.getHeight()
                        + ") with the reference solution" + (copy ? "; copied the scene to " + sceneRel : ""));
                commit(a, updated, extra, out);
                out.println("Students compare with: ./raylab render " + sceneRel + " --compare " + refRel
                        + " (tolerance " + GradingPlan.percent(tolerance) + " by default)");
                return 0;
            } finally {
                Files.deleteIfExists(tmp);
            }
        }
    }

    /** {@code raylab assignment add-case MILESTONE CASES.json [--points N] [--visible]}. */
    @Command(name = "add-case", mixinStandardHelpOptions = true,
            description = {"Add data cases (a JSON case object or an array of them) to a milestone.",
                "They are appended to the milestone's cases/added.json; the format is in grader/README.md."})
    public static final class AddCase extends Base implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "MILESTONE", description = "The milestone id (sphere, box, ...).")
        String milestoneId;

        @Parameters(index = "1", paramLabel = "CASES.json", description = "A case object or an array of cases.")
        Path cases;

        @Option(names = "--points", paramLabel = "N", description = "Points of each case (default: the case's own, else 1).")
        Double points;

        @Option(names = "--visible", description = "Students see the case: it ships in the starter and runs in check.")
        boolean visible;

        @Override
        public Integer call() throws Exception {
            PrintWriter out = spec.commandLine().getOut();
            Assignments all = load();
            Assignment a = milestone(all, milestoneId);
            Path root = project();
            ObjectMapper m = new ObjectMapper();
            JsonNode given;
            try {
                given = m.readTree(cases.toFile());
            } catch (IOException e) {
                throw UserError.badInput(cases + ": not valid JSON: " + String.valueOf(e.getMessage()).split("\n")[0]);
            }
            Path file = root.resolve(a.folder()).resolve("cases/added.json");
            ArrayNode list = Files.isRegularFile(file) && m.readTree(file.toFile()) instanceof ArrayNode arr ? arr
                    : m.createArrayNode();
            double added = 0;
            for (JsonNode c : given.isArray() ? given : List.of(given)) {
                if (!(c instanceof ObjectNode o)) {
                    throw UserError.badInput(cases + ": a case must be a JSON object");
                }
                if (points != null) {
                    o.put("points", points);
                }
                if (visible) {
                    o.put("visibility", "visible");
                }
                added += o.path("points").asDouble(1);
                list.add(o);
            }
            if (added != Math.rint(added)) {
                throw UserError.badInput("the new cases' points add up to " + added + ": the total must stay whole");
            }
            String json = Files.readString(root.resolve(a.folder()).resolve("assignment.json"), StandardCharsets.UTF_8);
            String updated = a.cases().contains("cases/added.json") ? json : addToArray(json, "cases", "\"cases/added.json\"");
            updated = withTotal(updated, a.points() + (int) added);
            byte[] text = (m.writerWithDefaultPrettyPrinter().writeValueAsString(list) + "\n").getBytes(StandardCharsets.UTF_8);
            try {
                // The grader's check of the format, before anything is written.
                Path probe = Files.createTempDirectory("raylab-cases");
                try {
                    Files.write(probe.resolve("added.json"), text);
                    raylab.grade.DataCases.load(probe.getParent(), new Assignment(a.id(), a.order(), a.title(), a.points(),
                            a.requires(), a.files(), a.tests(), List.of(), List.of("added.json"), a.optional(),
                            probe.getFileName()));
                } finally {
                    Files.deleteIfExists(probe.resolve("added.json"));
                    Files.deleteIfExists(probe);
                }
            } catch (IOException e) {
                throw UserError.badInput(e.getMessage().replaceFirst("^.*added\\.json", cases.toString()));
            }
            out.println("added " + (given.isArray() ? given.size() : 1) + " case(s) to " + root.relativize(file)
                    + (visible ? " (visible: shipped in the starter, run by check)" : " (hidden)"));
            commit(a, updated, Map.of(file, text), out);
            return 0;
        }
    }

    /** The text with an item appended to the top-level array {@code key} (created if missing). */
    static String addToArray(String json, String key, String item) throws IOException {
        Matcher m = Pattern.compile("\"" + Pattern.quote(key) + "\"\\s*:\\s*\\[").matcher(json);
        if (m.find()) {
            int open = m.end();
            int depth = 1;
            int i = open;
            boolean inString = false;
            for (; i < json.length() && depth > 0; i++) {
                char c = json.charAt(i);
                if (inString) {
                    if (c == '\\') {
                        i++;
                    } else if (c == '"') {
                        inString = false;
                    }
                } else if (c == '"') {
                    inString = true;
                } else if (c == '[' || c == '{') {
                    depth++;
                } else if (c == ']' || c == '}') {
                    depth--;
                }
            }
            int close = i - 1;
            String inside = json.substring(open, close);
            String indent = "    ";
            if (inside.isBlank()) {
                return json.substring(0, open) + "\n" + indent + item + "\n  " + json.substring(close);
            }
            String trimmed = inside.stripTrailing();
            return json.substring(0, open) + trimmed + ",\n" + indent + item + inside.substring(trimmed.length())
                    + json.substring(close);
        }
        int end = json.lastIndexOf('}');
        if (end < 0) {
            throw new IOException("assignment.json is not a JSON object");
        }
        String head = json.substring(0, end).stripTrailing();
        return head + ",\n  \"" + key + "\": [\n    " + item + "\n  ]\n" + json.substring(end);
    }

    /** The text with the milestone's top-level "points" set. */
    static String withTotal(String json, int points) throws IOException {
        // The top-level "points" is the first one, before "files", "tests" and "scenes".
        Matcher m = Pattern.compile("\"points\"\\s*:\\s*\\d+").matcher(json);
        if (!m.find()) {
            throw new IOException("assignment.json has no \"points\"");
        }
        return json.substring(0, m.start()) + "\"points\": " + points + json.substring(m.end());
    }

    private static void write(Path target, byte[] bytes) throws IOException {
        Files.createDirectories(target.getParent());
        Path tmp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".tmp");
        try {
            Files.write(tmp, bytes);
            try {
                // A temporary file is 0600; course files are read by others (the grader's sandbox user).
                Files.setPosixFilePermissions(tmp, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system
            }
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    private static List<Path> concat(List<Path> a, java.util.Collection<Path> b) {
        List<Path> out = new java.util.ArrayList<>(a);
        out.addAll(b);
        return out;
    }

    /** A tolerance as short decimal text: 0.002, not 0.0020000000000000000416. */
    static final class BigDecimalText {
        static String of(double v) {
            return new java.math.BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
        }
    }
}
