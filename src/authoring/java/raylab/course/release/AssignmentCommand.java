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
import raylab.cli.OptionalCommand;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.grade.VariantProposal;
import raylab.grade.VariantSpec;
import raylab.render.PngFiles;
import raylab.scene.SceneLoader;

/**
 * {@code raylab assignment add-scene|add-case|add-test} ({@link AddTestCommand}): grows a milestone in one command (instructors;
 * the starter leaves this class out). Each command changes {@code assignment.json} (the item and
 * the milestone's total), rewrites the handout's grading table from it, and shows what students
 * will see; every file is written to a temporary name and moved, and nothing is changed when a
 * step fails.
 *
 * <p>One command with three subcommands that share the same read, change and atomic write of {@code
 * assignment.json} and the handout.
 */
@Command(name = "assignment", mixinStandardHelpOptions = true,
        description = {"Add a graded scene, data cases or a hidden test to a milestone (instructors).",
            "Updates assignment.json, the milestone's points and its handout's grading table. See docs/instructors.md."},
        subcommands = {AssignmentCommand.AddScene.class, AssignmentCommand.AddCase.class, AddTestCommand.class})
public final class AssignmentCommand implements Callable<Integer>, OptionalCommand {
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

    /** {@code raylab assignment add-scene MILESTONE SCENE.json --points N [--tolerance T] [--variant SPEC]}. */
    @Command(name = "add-scene", mixinStandardHelpOptions = true,
            description = {"Render a scene's reference image and grade it in a milestone, on variants.",
                "The scene is copied into scenes/ if it is elsewhere; the reference goes to scenes/reference/NAME.png.",
                "Its \"variant\" (default: one made from the scene's camera and lights) is checked on the spot",
                "with the grader's own check: the first draw of every checked grading seed must keep the point."},
            exitCodeListHeading = "%nExit status:%n",
            exitCodeList = {"0:added", "1:the reference render failed, or no variant keeps the scene's point (nothing changed)",
                "2:bad input, or a scene that would be graded as published (nothing changed)"})
    public static final class AddScene extends Base implements Callable<Integer> {
        /** Grading seeds a variant is checked on before it is written. */
        static final int CHECK_SEEDS = 8;

        @Parameters(index = "0", paramLabel = "MILESTONE", description = "The milestone id (sphere, box, ...).")
        String milestoneId;

        @Parameters(index = "1", paramLabel = "SCENE.json", description = "The scene file.")
        Path scene;

        @Option(names = "--points", required = true, paramLabel = "N", description = "Points for a match (whole, >= 0; 0: a feedback-only scene, graded and shown with its"
                + " pixel feedback but earning nothing).")
        int points;

        @Option(names = "--tolerance", paramLabel = "T",
                description = "Fraction of pixels allowed to differ by more than 2/255 (default: the milestone's, "
                        + "the most common among its scenes; 0.002 for its first).")
        Double tolerance;

        @Option(names = "--variant", paramLabel = "SPEC",
                description = "The scene's \"variant\" as JSON, e.g. '{\"camera\": {\"yaw\": 10}}' (format: "
                        + "docs/assignment-format.md); default: one made from the scene's camera and lights. "
                        + "'none' is refused: students have the published scene's reference.")
        String variant;

        @Option(names = "--check-seeds", paramLabel = "N", description = "Grading seeds the variant is checked on "
                + "(default: ${DEFAULT-VALUE}).")
        int checkSeeds = CHECK_SEEDS;

        @Override
        public Integer call() throws Exception {
            PrintWriter out = spec.commandLine().getOut();
            if (points < 0) {
                throw UserError.badInput("--points must be 0 or more, got " + points);
            }
            if (tolerance != null && !(tolerance >= 0 && tolerance < 1)) {
                throw UserError.badInput("--tolerance must be a fraction in [0, 1), got " + tolerance);
            }
            if (checkSeeds < 1) {
                throw UserError.badInput("--check-seeds must be at least 1, got " + checkSeeds);
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
            if (variant != null && variant.strip().equals("none")) {
                throw UserError.badInput("WARNING: " + name + " would be graded as published: its reference PNG ships "
                        + "in the starter, so a copied image earns its " + points + " point(s). Nothing was changed; "
                        + "give it a --variant (or leave the option out for the default one), docs/instructors.md "
                        + "\"Adding a scene\"");
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
            double tol = tolerance != null ? tolerance : milestoneTolerance(a);
            JsonNode spec = checkedVariant(name.replaceFirst("\\.json$", ""), out);
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
                        "{\"scene\": \"%s\", \"reference\": \"%s\", \"points\": %d, \"tolerance\": %s,%n     \"variant\": %s}",
                        sceneRel, refRel, points, BigDecimalText.of(tol), VariantProposal.text(spec));
                String json = Files.readString(root.resolve(a.folder()).resolve("assignment.json"), StandardCharsets.UTF_8);
                String updated = withTotal(addToArray(json, "scenes", entry), a.points() + points);
                out.println("rendered the reference " + refRel + " (" + image.getWidth() + "x" + image.getHeight()
                        + ") with the reference solution" + (copy ? "; copied the scene to " + sceneRel : ""));
                commit(a, updated, extra, out);
                out.println("Students compare with: ./raylab render " + sceneRel + " --compare " + refRel
                        + " (tolerance " + GradingPlan.percent(tol) + " by default); the grader grades variants of it:"
                        + " ./raylab variant " + sceneRel + " --seed N -o v.png shows one");
                return 0;
            } finally {
                Files.deleteIfExists(tmp);
            }
        }

        /**
         * The variant to write: the given one if it keeps the point on every checked seed, or the
         * default (narrowed up to twice when it does not); a one-line error and nothing changed
         * when none does.
         */
        private JsonNode checkedVariant(String sceneName, PrintWriter out) throws IOException {
            JsonNode published = new ObjectMapper().readTree(scene.toFile());
            long seed0 = 20261204L;
            try {
                if (variant != null) {
                    JsonNode given;
                    try {
                        given = new ObjectMapper().readTree(variant);
                    } catch (IOException e) {
                        throw UserError.badInput("--variant: not valid JSON: " + String.valueOf(e.getMessage()).split("\n")[0]);
                    }
                    if (given == null || !given.isObject()) {
                        throw UserError.badInput("--variant: a JSON object, e.g. '{\"camera\": {\"yaw\": 10}}', got " + variant);
                    }
                    VariantProposal.Checked c = VariantProposal.check(published, scene, given, sceneName, checkSeeds, seed0);
                    if (!c.keepsThePoint()) {
                        throw new UserError("the --variant loses the scene's point on " + c.failures().size() + " of "
                                + checkSeeds + " grading seeds (first: " + c.failures().get(0) + "); narrow its bounds. "
                                + "Nothing was changed", 1);
                    }
                    out.println("variant " + VariantProposal.text(given) + ": the first draw keeps the point on each of "
                            + checkSeeds + " grading seeds (the grader's check)");
                    return given;
                }
                com.fasterxml.jackson.databind.node.ObjectNode spec = VariantProposal.defaultSpec(published);
                if (spec.isEmpty()) {
                    throw new UserError("WARNING: the default variant has nothing to move in " + scene.getFileName()
                            + " (no lights, and a camera without " + (published.path("camera").path("type").asText("")
                                    .equals("orthographic") ? "viewDirection" : "lookAt") + "), so it would be graded as"
                            + " published and a copied reference would score; nothing was changed: give a --variant with"
                            + " \"placement\" (docs/assignment-format.md)", 1);
                }
                String first = "";
                for (int k = 0; k < 3; k++) {
                    VariantProposal.Checked c = VariantProposal.check(published, scene, spec, sceneName, checkSeeds, seed0);
                    if (c.keepsThePoint()) {
                        out.println("variant " + VariantProposal.text(spec) + (k == 0 ? " (the default for its content)"
                                : " (the default narrowed " + k + " time(s): " + first + ")")
                                + ": the first draw keeps the point on each of " + checkSeeds
                                + " grading seeds (the grader's check)");
                        return spec;
                    }
                    if (k == 0) {
                        first = c.failures().get(0);
                    }
                    spec = VariantProposal.narrower(spec);
                }
                throw new UserError("WARNING: no default variant keeps the point of " + scene.getFileName()
                        + " (" + first + "), so it would be graded as published and a copied reference would score;"
                        + " nothing was changed: give a --variant that keeps what it tests (docs/assignment-format.md)", 1);
            } catch (VariantSpec.Invalid e) {
                throw UserError.badInput("--variant: " + e.getMessage());
            } catch (RuntimeException e) {
                if (e instanceof UserError) {
                    throw e;
                }
                // The grader could not vary this camera this way (a perspective camera without lookAt, ...).
                throw UserError.badInput("--variant: the grader cannot vary " + scene.getFileName() + " this way: "
                        + e + " (docs/assignment-format.md, \"Graded scene variants\")");
            } catch (raylab.scene.SceneException e) {
                throw UserError.badInput(e.getMessage());
            }
        }

        /** The tolerance most of the milestone's scenes have (the smallest of the most common); 0.002 for none. */
        static double milestoneTolerance(Assignment a) {
            Map<Double, Integer> count = new java.util.TreeMap<>();
            for (Assignment.GradedScene g : a.scenes()) {
                count.merge(g.tolerance(), 1, Integer::sum);
            }
            double best = 0.002;
            int n = 0;
            for (Map.Entry<Double, Integer> e : count.entrySet()) {
                if (e.getValue() > n) {
                    best = e.getKey();
                    n = e.getValue();
                }
            }
            return best;
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
