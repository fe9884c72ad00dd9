package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.JavaBuild;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.shading.ShadingPoint;

/**
 * No silent loss in the shade loop (issue 37, item 5), checked with mistakes nobody wrote down:
 * a seeded generator of mutants of the lecture's {@code shade()} loop (which term is added under
 * which condition, which test decides "in front", the ambient term once, never, per light or
 * only when unlit, overwriting instead of adding, a loop that stops early or skips a light, the
 * wrong light's direction, shadow answer or terms). Each mutant is compiled as
 * {@code raylab.shading.Shading} and run against what a student sees before submission for
 * milestone lambert, the one that grades the loop: the visible tests named in
 * {@code assignments/04-lambert/assignment.json} (run with JUnit in a class loader where the
 * mutant is {@code Shading}) and, when they all pass, the milestone's visible scenes rendered and
 * compared with their published references at the graded tolerance.
 *
 * <p>A mutant that computes something else than the reference for some point, light set and
 * material of the course (Lambertian, Blinn-Phong; seeded random points with the viewer anywhere
 * above the surface, lights at the point, on the horizon and behind it, random blockers) must be
 * caught by one of them. A mutant that never computes anything else is equivalent (a light
 * behind the surface adds a diffuse term of max(0, n·l) = 0 anyway) and is listed, not required.
 * The grid of terms and conditions this covers is in docs/shading.md, "Where a mistake in the
 * loop shows".
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ShadeLoopMutantsTest {
    /** The seed of the random mutants (and of the equivalence search); -Draylab.mutants.seed=N to vary it. */
    static final long SEED = Long.getLong("raylab.mutants.seed", 37_005L);
    /** How many random mutants beside the exhaustive ones. */
    static final int RANDOM = Integer.getInteger("raylab.mutants.random", 120);

    /** "In front of the surface": the test that drops a light that faces away. */
    enum Facing {
        N_DOT_L_POSITIVE("at.n.dot(l) > 0"), N_DOT_L_NOT_NEGATIVE("at.n.dot(l) >= 0"), VIEWER_SIDE("at.v.dot(l) > 0"),
        TWO_SIDED("at.n.dot(l) != 0"), ALWAYS("true"), INVERTED("at.n.dot(l) < 0");

        final String code;

        Facing(String code) {
            this.code = code;
        }
    }

    /** The direction l handed to the terms (and to the facing test). */
    enum Direction {
        TO_LIGHT("at.toLight(%s)"), UNNORMALIZED("%s.position.minus(at.x)"), REVERSED("at.toLight(%s).negate()");

        final String code;

        Direction(String code) {
            this.code = code;
        }
    }

    /** When one light's term is added, from "in front" and "visible" (not blocked). */
    enum Gate {
        FRONT_AND_VISIBLE("front && visible"), FRONT("front"), VISIBLE("visible"), ALWAYS("true"), NEVER("false"),
        FRONT_AND_BLOCKED("front && !visible"), BEHIND_AND_VISIBLE("!front && visible"), FRONT_OR_VISIBLE("front || visible");

        final String code;

        Gate(String code) {
            this.code = code;
        }
    }

    /** Where the ambient term ka·Ia goes. */
    enum Ambient {
        ONCE, NEVER, PER_LIGHT, WITH_EACH_LIT_LIGHT, ONLY_WHEN_NOTHING_LIT, AFTER_THE_LOOP
    }

    /** How a lit light's terms reach the result. */
    enum Accumulate {
        ADD, OVERWRITE, OVERWRITE_KEEPING_AMBIENT
    }

    /** Which lights the loop visits. */
    enum Loop {
        EVERY_LIGHT, BREAK_AT_A_SKIPPED_LIGHT, FIRST_ONLY, ALL_BUT_THE_FIRST, LAST_ONLY
    }

    /** One mutant of the loop: each choice at its reference value but for the mutated ones. */
    record Mutant(Facing facing, Direction direction, Gate diffuse, Gate specular, Ambient ambient, Accumulate accumulate,
            Loop loop, boolean firstLightsDirection, boolean firstLightsShadow, boolean firstLightsTerms) {
        static final Mutant REFERENCE = new Mutant(Facing.N_DOT_L_POSITIVE, Direction.TO_LIGHT, Gate.FRONT_AND_VISIBLE,
                Gate.FRONT_AND_VISIBLE, Ambient.ONCE, Accumulate.ADD, Loop.EVERY_LIGHT, false, false, false);

        /** The choices' positions in {@link #values()}. */
        static final int FACING = 0, DIRECTION = 1, DIFFUSE = 2, SPECULAR = 3, AMBIENT = 4, ACCUMULATE = 5, LOOP = 6,
                FIRST_LIGHTS_DIRECTION = 7, FIRST_LIGHTS_SHADOW = 8, FIRST_LIGHTS_TERMS = 9;

        /** This mutant with one choice changed. */
        Mutant with(int choice, Object value) {
            Object[] v = values();
            v[choice] = value;
            return new Mutant((Facing) v[0], (Direction) v[1], (Gate) v[2], (Gate) v[3], (Ambient) v[4], (Accumulate) v[5],
                    (Loop) v[6], (Boolean) v[7], (Boolean) v[8], (Boolean) v[9]);
        }

        /** The choices that differ from the reference, e.g. "specular=FRONT, loop=FIRST_ONLY". */
        String changes() {
            List<String> c = new ArrayList<>();
            Object[] mine = values();
            Object[] ref = REFERENCE.values();
            String[] names = {"facing", "direction", "diffuse", "specular", "ambient", "accumulate", "loop",
                "firstLightsDirection", "firstLightsShadow", "firstLightsTerms"};
            for (int i = 0; i < names.length; i++) {
                if (!mine[i].equals(ref[i])) {
                    c.add(names[i] + "=" + mine[i]);
                }
            }
            return c.isEmpty() ? "none (the reference's choices)" : String.join(", ", c);
        }

        Object[] values() {
            return new Object[] {facing, direction, diffuse, specular, ambient, accumulate, loop, firstLightsDirection,
                firstLightsShadow, firstLightsTerms};
        }

        /** The body of shade(at, lights), as a student would have written it. */
        String body() {
            String first = "lights.get(0)";
            StringBuilder b = new StringBuilder();
            b.append("Color result = ").append(ambient == Ambient.ONCE ? "at.ambient()" : "Color.BLACK").append(";\n");
            b.append("boolean anyLit = false;\n");
            String from = switch (loop) {
                case ALL_BUT_THE_FIRST -> "1";
                case LAST_ONLY -> "Math.max(0, lights.size() - 1)";
                default -> "0";
            };
            b.append("for (int i = ").append(from).append("; i < lights.size(); i++) {\n");
            b.append("    PointLight light = lights.get(i);\n");
            if (ambient == Ambient.PER_LIGHT) {
                b.append("    result = result.plus(at.ambient());\n");
            }
            b.append("    Vec3 l = ").append(String.format(Locale.ROOT, direction.code, firstLightsDirection ? first : "light"))
                    .append(";\n");
            b.append("    boolean front = ").append(facing.code).append(";\n");
            b.append("    boolean visible = at.visible(").append(firstLightsShadow ? first : "light").append(");\n");
            if (loop == Loop.BREAK_AT_A_SKIPPED_LIGHT) {
                b.append("    if (!(front && visible)) {\n        break;\n    }\n");
            }
            String termsOf = firstLightsTerms ? first : "light";
            b.append("    Color terms = Color.BLACK;\n    boolean lit = false;\n");
            b.append("    if (").append(diffuse.code).append(") {\n        terms = terms.plus(at.diffuse(").append(termsOf)
                    .append(", l));\n        lit = true;\n    }\n");
            b.append("    if (").append(specular.code).append(") {\n        terms = terms.plus(at.specular(").append(termsOf)
                    .append(", l));\n        lit = true;\n    }\n");
            if (ambient == Ambient.WITH_EACH_LIT_LIGHT) {
                b.append("    if (lit) {\n        terms = terms.plus(at.ambient());\n    }\n");
            }
            b.append("    anyLit |= lit;\n");
            b.append(switch (accumulate) {
                case ADD -> "    result = result.plus(terms);\n";
                case OVERWRITE -> "    if (lit) {\n        result = terms;\n    }\n";
                case OVERWRITE_KEEPING_AMBIENT -> "    if (lit) {\n        result = at.ambient().plus(terms);\n    }\n";
            });
            if (loop == Loop.FIRST_ONLY) {
                b.append("    break;\n");
            }
            b.append("}\n");
            if (ambient == Ambient.AFTER_THE_LOOP) {
                b.append("result = result.plus(at.ambient());\n");
            }
            if (ambient == Ambient.ONLY_WHEN_NOTHING_LIT) {
                b.append("if (!anyLit) {\n    result = result.plus(at.ambient());\n}\n");
            }
            b.append("return result;\n");
            return b.toString();
        }

        /** A random mutant: each choice changed with probability 0.3. */
        static Mutant random(SplittableRandom r) {
            return new Mutant(pick(r, Facing.values(), REFERENCE.facing), pick(r, Direction.values(), REFERENCE.direction),
                    pick(r, Gate.values(), REFERENCE.diffuse), pick(r, Gate.values(), REFERENCE.specular),
                    pick(r, Ambient.values(), REFERENCE.ambient), pick(r, Accumulate.values(), REFERENCE.accumulate),
                    pick(r, Loop.values(), REFERENCE.loop), r.nextInt(10) < 3, r.nextInt(10) < 3, r.nextInt(10) < 3);
        }

        static <T> T pick(SplittableRandom r, T[] values, T reference) {
            return r.nextInt(10) < 3 ? values[r.nextInt(values.length)] : reference;
        }
    }

    /**
     * The reference's choices first; then every single change (each choice alone); every pair of
     * gates of the diffuse and the specular term (the terms × the conditions "blocked" and "in
     * front"); then {@link #RANDOM} seeded random mutants. Duplicates once.
     */
    static List<Mutant> mutants(long seed) {
        Set<Mutant> all = new LinkedHashSet<>();
        Mutant ref = Mutant.REFERENCE;
        all.add(ref);
        Object[][] choices = {Facing.values(), Direction.values(), Gate.values(), Gate.values(), Ambient.values(),
            Accumulate.values(), Loop.values(), {true}, {true}, {true}};
        for (int c = 0; c < choices.length; c++) {
            for (Object value : choices[c]) {
                all.add(ref.with(c, value));
            }
        }
        for (Gate dg : Gate.values()) {
            for (Gate sg : Gate.values()) {
                all.add(ref.with(Mutant.DIFFUSE, dg).with(Mutant.SPECULAR, sg));
            }
        }
        SplittableRandom r = new SplittableRandom(seed);
        for (int i = 0; i < RANDOM; i++) {
            all.add(Mutant.random(r));
        }
        return new ArrayList<>(all);
    }

    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    static Path dir;

    List<Mutant> mutants;
    /** The mutants, loaded. */
    Lambert loaded;
    /** Others loaded (the bundled submissions' Shading.java), closed at the end. */
    final List<Lambert> others = new ArrayList<>();

    static Path root() {
        return Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    }

    /** The solution region of the reference Shading.shade: mutant 0, the loop as shipped. */
    static String referenceBody() throws IOException {
        String src = Files.readString(root().resolve("src/main/java/raylab/shading/Shading.java"));
        int from = src.indexOf("// BEGIN SOLUTION lambert");
        int to = src.indexOf("// STUB", from);
        assertTrue(from > 0 && to > from, "no solution region in Shading.java");
        return src.substring(src.indexOf('\n', from) + 1, to);
    }

    @BeforeAll
    void compileTheMutants() throws Exception {
        mutants = mutants(SEED);
        StringBuilder src = new StringBuilder("package raylab.shading;\n\nimport java.util.List;\n\n"
                + "import raylab.light.PointLight;\nimport raylab.math.Color;\nimport raylab.math.Vec3;\n\n"
                + "/** Mutants of the shade loop (ShadeLoopMutantsTest): body 0 is the reference's own. */\n"
                + "public final class Shading {\n    public static int mutant;\n\n"
                + "    public static Color shade(ShadingPoint at, List<PointLight> lights) {\n        switch (mutant) {\n");
        for (int k = 0; k <= mutants.size(); k++) {
            src.append("            case ").append(k).append(": return m").append(k).append("(at, lights);\n");
        }
        src.append("            default: throw new IllegalStateException(\"no mutant \" + mutant);\n        }\n    }\n\n");
        src.append("    static Color m0(ShadingPoint at, List<PointLight> lights) {\n").append(referenceBody()).append("    }\n");
        for (int k = 0; k < mutants.size(); k++) {
            src.append("\n    static Color m").append(k + 1).append("(ShadingPoint at, List<PointLight> lights) {\n")
                    .append(mutants.get(k).body().indent(8)).append("    }\n");
        }
        src.append("}\n");
        Path file = dir.resolve("src/raylab/shading/Shading.java");
        Files.createDirectories(file.getParent());
        Files.writeString(file, src);
        loaded = new Lambert(file, dir.resolve("classes"));
    }

    /**
     * Milestone lambert as a student sees it before submission, with one Shading.java compiled in
     * place of the reference's: its visible tests (from assignment.json) and visible scenes, in a
     * class loader of their own where that Shading is the one every raylab class links to.
     */
    static final class Lambert implements AutoCloseable {
        final URLClassLoader loader;
        final Class<?> shading;
        final Class<?> probe;
        final List<Class<?>> visibleTests = new ArrayList<>();
        /** The visible scenes: path, reference, tolerance. */
        final List<String[]> scenes = new ArrayList<>();

        Lambert(Path source, Path classes) throws Exception {
            JavaBuild.Result r = JavaBuild.compile(List.of(source), JavaBuild.ownClassPath(), classes);
            assertTrue(r.success(), source + " does not compile: " + r.errors());
            List<URL> urls = new ArrayList<>(List.of(classes.toUri().toURL()));
            for (Path p : JavaBuild.ownClassPath()) {
                if (Files.isDirectory(p)) {
                    urls.add(p.toUri().toURL()); // target/test-classes and target/classes, after Shading
                }
            }
            loader = new ChildFirst(urls.toArray(URL[]::new), ShadeLoopMutantsTest.class.getClassLoader());
            shading = loader.loadClass("raylab.shading.Shading");
            probe = loader.loadClass(Probe.class.getName());
            assertTrue(shading.getClassLoader() == loader && probe.getClassLoader() == loader, "not loaded child-first");
            JsonNode lambert = JSON.readTree(root().resolve("assignments/04-lambert/assignment.json").toFile());
            for (JsonNode t : lambert.get("tests").get("visible")) {
                String path = t.asText();
                String name = path.substring("src/test/java/".length(), path.length() - ".java".length()).replace('/', '.');
                visibleTests.add(loader.loadClass(name));
            }
            for (JsonNode s : lambert.get("scenes")) {
                scenes.add(new String[] {root().resolve(s.get("scene").asText()).toString(),
                    root().resolve(s.get("reference").asText()).toString(), s.get("tolerance").asText()});
            }
            assertTrue(visibleTests.size() >= 2 && !scenes.isEmpty(), "lambert's visible tests and scenes: " + visibleTests);
        }

        /** The failed visible tests: display name and the first line of the message. */
        Map<String, String> visibleFailures() {
            Map<String, String> failed = new LinkedHashMap<>();
            LauncherDiscoveryRequestBuilder request = LauncherDiscoveryRequestBuilder.request();
            visibleTests.forEach(c -> request.selectors(DiscoverySelectors.selectClass(c)));
            LauncherDiscoveryRequest built = request.build();
            Launcher launcher = LauncherFactory.create();
            Thread t = Thread.currentThread();
            ClassLoader before = t.getContextClassLoader();
            t.setContextClassLoader(loader);
            try {
                launcher.execute(built, new TestExecutionListener() {
                    @Override
                    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
                        if (id.isTest() && result.getStatus() != TestExecutionResult.Status.SUCCESSFUL) {
                            String message = result.getThrowable().map(Throwable::getMessage).orElse("");
                            failed.put(id.getDisplayName(), message == null ? "" : message.lines().findFirst().orElse(""));
                        }
                    }
                });
            } finally {
                t.setContextClassLoader(before);
            }
            return failed;
        }

        /** The first visible scene rendered outside its tolerance, with the comparison; or null. */
        String sceneFailure() throws ReflectiveOperationException {
            for (String[] s : scenes) {
                String r = (String) probe.getMethod("sceneDiffers", String.class, String.class, double.class).invoke(null,
                        s[0], s[1], Double.parseDouble(s[2]));
                if (r != null) {
                    return Path.of(s[0]).getFileName() + ": " + r;
                }
            }
            return null;
        }

        @Override
        public void close() throws IOException {
            loader.close();
        }
    }

    @AfterAll
    void close() throws IOException {
        if (loaded != null) {
            loaded.close();
        }
        for (Lambert l : others) {
            l.close();
        }
    }

    /** Loads raylab's classes (and the mutant Shading) itself, everything else from the parent. */
    static final class ChildFirst extends URLClassLoader {
        ChildFirst(URL[] urls, ClassLoader parent) {
            super(urls, parent);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (!name.startsWith("raylab.")) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> c = findLoadedClass(name);
                if (c == null) {
                    try {
                        c = findClass(name);
                    } catch (ClassNotFoundException e) {
                        c = super.loadClass(name, false);
                    }
                }
                if (resolve) {
                    resolveClass(c);
                }
                return c;
            }
        }
    }

    void select(int body) throws ReflectiveOperationException {
        loaded.shading.getField("mutant").setInt(null, body);
    }

    Map<String, String> visibleFailures() {
        return loaded.visibleFailures();
    }

    String sceneFailure() throws ReflectiveOperationException {
        return loaded.sceneFailure();
    }

    /** An input where body k and the reference (body 0) differ, or null when none was found. */
    String difference(int k) throws ReflectiveOperationException {
        return (String) loaded.probe.getMethod("difference", int.class, long.class, int.class).invoke(null, k, SEED, 600);
    }

    @Test
    void theReferencesChoicesAreTheReferenceAndPassEverything() throws Exception {
        assertEquals(Mutant.REFERENCE, mutants.get(0));
        assertNull(difference(1), "the generator's reference choices compute what the reference does:\n" + mutants.get(0).body());
        select(1);
        assertEquals(Map.of(), visibleFailures(), "the reference's choices fail visible tests:\n" + mutants.get(0).body());
        assertNull(sceneFailure(), "the reference's choices fail a visible scene");
        select(0);
        assertEquals(Map.of(), visibleFailures(), "the reference itself fails visible tests");
    }

    @Test
    void theEquivalenceSearchFindsTheCorpusMistakes() throws Exception {
        // The mistakes of the corpus, as choices: each differs from the reference on some input.
        Map<String, Mutant> corpus = new LinkedHashMap<>();
        Mutant r = Mutant.REFERENCE;
        corpus.put("bugs2: the ambient term once per light", r.with(Mutant.AMBIENT, Ambient.PER_LIGHT));
        corpus.put("lambert-shadow-ignored", r.with(Mutant.DIFFUSE, Gate.FRONT).with(Mutant.SPECULAR, Gate.FRONT));
        corpus.put("lambert-shadow-gates-diffuse-only", r.with(Mutant.SPECULAR, Gate.FRONT));
        for (Map.Entry<String, Mutant> e : corpus.entrySet()) {
            int k = mutants.indexOf(e.getValue());
            assertTrue(k >= 0, e.getKey() + " is not among the generated mutants");
            assertNotNull(difference(k + 1), e.getKey() + " (" + e.getValue().changes() + ") was found equivalent");
        }
        // A diffuse term kept for a light behind the surface adds max(0, n·l) = 0: equivalent.
        Mutant behind = r.with(Mutant.DIFFUSE, Gate.VISIBLE);
        assertNull(difference(mutants.indexOf(behind) + 1), "the diffuse term of a light behind is 0");
    }

    static final String NO_LIGHTS = "no lights: only the ambient term ka·Ia";
    static final String TWO_LIGHTS = "two lights add up, the ambient term is added once";
    static final String BLOCKED = "a light in shadow adds nothing (and the ambient term stays)";
    static final String BEHIND = "a light behind the surface adds nothing";
    static final String BOTH_TERMS = "each visible light adds its diffuse and its specular term";

    /**
     * The checks the mutants called for (a light at the point or on the horizon with a highlight, a
     * grazing viewer) were added inside existing visible tests, so lambert's visible points are
     * still split among the same methods; and each Shading.java of the nine bundled submissions
     * fails exactly the visible tests it failed before, so their scores stay as they are.
     */
    @Test
    void theBundledSubmissionsFailTheSameVisibleTestsAsBefore() throws Exception {
        Map<String, Set<String>> expected = new LinkedHashMap<>();
        expected.put("src/main/java/raylab/shading/Shading.java", Set.of());
        expected.put("alternatives/Shading.java", Set.of());
        expected.put("lecture/shading-lecture-order/Shading.java", Set.of());
        expected.put("bugs2/Shading.java", Set.of(NO_LIGHTS, TWO_LIGHTS, BLOCKED, BEHIND, BOTH_TERMS));
        expected.put("mistakes/lambert-shadow-ignored/Shading.java", Set.of(BLOCKED));
        expected.put("mistakes/lambert-shadow-gates-diffuse-only/Shading.java", Set.of(BLOCKED));
        int n = 0;
        for (Map.Entry<String, Set<String>> e : expected.entrySet()) {
            Path file = e.getKey().startsWith("src/") ? root().resolve(e.getKey())
                    : root().resolve("src/test/resources/submissions").resolve(e.getKey());
            Path src = dir.resolve("bundled" + n + "/src/raylab/shading/Shading.java");
            Files.createDirectories(src.getParent());
            Files.copy(file, src);
            Lambert l = new Lambert(src, dir.resolve("bundled" + n++ + "/classes"));
            others.add(l);
            assertEquals(e.getValue(), l.visibleFailures().keySet(), e.getKey() + ": the visible tests of lambert it fails");
        }
    }

    static final String ONE_LIGHT = "one light above: ka·Ia + kd·I·(n·l)";
    static final String NO_HIGHLIGHT_BEHIND = "a light behind the surface gives no highlight either";
    static final String AT_THE_POINT = "a light exactly at the point adds nothing, and no NaN";
    static final String EQUIVALENT = "equivalent";

    /** One cell of the grid: a term, a condition, a mistake in that pair, and the visible test that shows it. */
    record Cell(String term, String condition, String mistake, Mutant mutant, String shownBy) {
    }

    /**
     * The grid of grader/README.md ("The shade loop: where each mistake shows"), row by row: the
     * terms (ambient; each light's diffuse; each light's specular) under each condition that drops
     * or keeps them (a blocked light; a light behind the surface, n·l &lt; 0; a light on the
     * horizon or exactly at x, n·l = 0; a viewer off the normal, where v·l and n·l differ; several
     * lights), each mistake a mutant of the generator.
     */
    static List<Cell> grid() {
        Mutant r = Mutant.REFERENCE;
        return List.of(
                new Cell("ambient", "no light", "left out", r.with(Mutant.AMBIENT, Ambient.NEVER), NO_LIGHTS),
                new Cell("ambient", "a lit light", "only when no light is lit", r.with(Mutant.AMBIENT, Ambient.ONLY_WHEN_NOTHING_LIT),
                        ONE_LIGHT),
                new Cell("ambient", "blocked", "only with a lit light (lost when every light is blocked)",
                        r.with(Mutant.AMBIENT, Ambient.WITH_EACH_LIT_LIGHT), BLOCKED),
                new Cell("ambient", "behind (n·l < 0)", "only with a lit light (lost when the light is behind)",
                        r.with(Mutant.AMBIENT, Ambient.WITH_EACH_LIT_LIGHT), NO_HIGHLIGHT_BEHIND),
                new Cell("ambient", "several lights", "once per light", r.with(Mutant.AMBIENT, Ambient.PER_LIGHT), TWO_LIGHTS),
                new Cell("ambient", "several lights", "lost when a lit light overwrites the result",
                        r.with(Mutant.ACCUMULATE, Accumulate.OVERWRITE), TWO_LIGHTS),
                new Cell("diffuse", "in front and visible", "left out", r.with(Mutant.DIFFUSE, Gate.NEVER), ONE_LIGHT),
                new Cell("diffuse", "blocked", "kept", r.with(Mutant.DIFFUSE, Gate.FRONT), BLOCKED),
                new Cell("diffuse", "blocked", "added only when blocked", r.with(Mutant.DIFFUSE, Gate.FRONT_AND_BLOCKED), ONE_LIGHT),
                new Cell("diffuse", "behind (n·l < 0)", "kept (kd·I·max(0, n·l) = 0: no other result)", r.with(Mutant.DIFFUSE, Gate.VISIBLE),
                        EQUIVALENT),
                new Cell("diffuse", "behind (n·l < 0)", "in front taken for behind (n·l < 0 as the test)",
                        r.with(Mutant.FACING, Facing.INVERTED), ONE_LIGHT),
                new Cell("diffuse", "viewer off the normal", "in front decided by v·l instead of n·l",
                        r.with(Mutant.FACING, Facing.VIEWER_SIDE), BEHIND),
                new Cell("diffuse", "several lights", "the last lit light overwrites the others",
                        r.with(Mutant.ACCUMULATE, Accumulate.OVERWRITE_KEEPING_AMBIENT), TWO_LIGHTS),
                new Cell("diffuse", "several lights", "the first light only", r.with(Mutant.LOOP, Loop.FIRST_ONLY), TWO_LIGHTS),
                new Cell("diffuse", "several lights", "the first light skipped", r.with(Mutant.LOOP, Loop.ALL_BUT_THE_FIRST), ONE_LIGHT),
                new Cell("diffuse", "several lights", "the loop stops at a skipped light (break for continue)",
                        r.with(Mutant.LOOP, Loop.BREAK_AT_A_SKIPPED_LIGHT), BEHIND),
                new Cell("diffuse", "several lights", "the first light's terms for every light",
                        r.with(Mutant.FIRST_LIGHTS_TERMS, true), TWO_LIGHTS),
                new Cell("diffuse", "several lights", "the first light's direction for every light",
                        r.with(Mutant.FIRST_LIGHTS_DIRECTION, true), TWO_LIGHTS),
                new Cell("diffuse", "several lights", "the first light's shadow answer for every light",
                        r.with(Mutant.FIRST_LIGHTS_SHADOW, true), BLOCKED),
                new Cell("specular", "in front and visible", "left out", r.with(Mutant.SPECULAR, Gate.NEVER), BOTH_TERMS),
                new Cell("specular", "blocked", "kept (the shadow test around the diffuse term only)",
                        r.with(Mutant.SPECULAR, Gate.FRONT), BLOCKED),
                new Cell("specular", "behind (n·l < 0)", "kept", r.with(Mutant.SPECULAR, Gate.VISIBLE), NO_HIGHLIGHT_BEHIND),
                new Cell("specular", "on the horizon or at x (n·l = 0)", "kept (n·l >= 0 as the test)",
                        r.with(Mutant.FACING, Facing.N_DOT_L_NOT_NEGATIVE), NO_HIGHLIGHT_BEHIND),
                new Cell("specular", "on the horizon or at x (n·l = 0)", "kept (n·l >= 0 as the test)",
                        r.with(Mutant.FACING, Facing.N_DOT_L_NOT_NEGATIVE), AT_THE_POINT),
                new Cell("specular", "behind (n·l < 0)", "kept for a light on either side (n·l != 0 as the test)",
                        r.with(Mutant.FACING, Facing.TWO_SIDED), NO_HIGHLIGHT_BEHIND),
                new Cell("specular", "viewer off the normal", "in front decided by v·l instead of n·l",
                        r.with(Mutant.FACING, Facing.VIEWER_SIDE), BEHIND),
                new Cell("specular", "several lights", "the last lit light overwrites the others",
                        r.with(Mutant.ACCUMULATE, Accumulate.OVERWRITE_KEEPING_AMBIENT), BOTH_TERMS),
                new Cell("specular", "several lights", "the first light's terms for every light",
                        r.with(Mutant.FIRST_LIGHTS_TERMS, true), BOTH_TERMS));
    }

    @Test
    void everyCellOfTheGridIsShownByItsVisibleTest() throws Exception {
        StringBuilder wrong = new StringBuilder();
        for (Cell c : grid()) {
            int k = mutants.indexOf(c.mutant());
            assertTrue(k > 0, c + ": not among the generated mutants");
            String diff = difference(k + 1);
            String got;
            if (c.shownBy().equals(EQUIVALENT)) {
                got = diff == null ? EQUIVALENT : "differs at " + diff;
            } else {
                select(k + 1);
                Set<String> failed = visibleFailures().keySet();
                got = failed.contains(c.shownBy()) ? c.shownBy() : "failed only " + failed;
            }
            System.out.printf(Locale.ROOT, "%-8s | %-34s | %-60s | %s%n", c.term(), c.condition(), c.mistake(), got);
            if (!got.equals(c.shownBy())) {
                wrong.append("\n  ").append(c.term()).append(" / ").append(c.condition()).append(" / ").append(c.mistake())
                        .append(" [").append(c.mutant().changes()).append("]: expected ").append(c.shownBy())
                        .append(", got ").append(got).append("\n").append(c.mutant().body());
            }
        }
        assertTrue(wrong.length() == 0, "cells of the grid not shown by their visible test:" + wrong);
    }

    @Test
    void everyMutantThatComputesSomethingElseFailsAVisibleTestOrScene() throws Exception {
        List<String> survivors = new ArrayList<>();
        List<String> equivalent = new ArrayList<>();
        Map<String, Integer> caughtBy = new LinkedHashMap<>();
        int observable = 0;
        for (int k = 1; k < mutants.size(); k++) {
            Mutant m = mutants.get(k);
            String diff = difference(k + 1);
            if (diff == null) {
                equivalent.add("[" + m.changes() + "]");
                continue;
            }
            observable++;
            select(k + 1);
            Map<String, String> failed = visibleFailures();
            String by;
            if (!failed.isEmpty()) {
                by = String.join(" | ", failed.keySet());
            } else {
                String scene = sceneFailure();
                by = scene == null ? null : "scene " + scene;
            }
            System.out.printf(Locale.ROOT, "mutant %3d [%s]: %s%n", k, m.changes(), by == null ? "NOT CAUGHT (" + diff + ")"
                    : "caught by " + by);
            if (by == null) {
                survivors.add("\n--- mutant " + k + " [" + m.changes() + "], differs from the reference at " + diff
                        + ":\n" + m.body());
            } else {
                failed.keySet().forEach(n -> caughtBy.merge(n, 1, Integer::sum));
            }
        }
        System.out.println("seed " + SEED + ": " + (mutants.size() - 1) + " mutants, " + observable + " compute something"
                + " else, " + equivalent.size() + " equivalent: " + String.join(" ", equivalent));
        caughtBy.forEach((n, c) -> System.out.printf(Locale.ROOT, "  %3d caught by %s%n", c, n));
        assertTrue(survivors.isEmpty(), "seed " + SEED + " (-Draylab.mutants.seed=" + SEED + "): " + survivors.size()
                + " mutant(s) of the shade loop pass every visible test and scene of lambert:" + String.join("", survivors));
    }

    /**
     * Runs inside the mutants' class loader (raylab's classes and the mutant Shading loaded
     * there): the equivalence search and the scenes.
     */
    public static final class Probe {
        private Probe() {
        }

        static Color shade(int body, ShadingPoint at, List<PointLight> lights) throws ReflectiveOperationException {
            Class<?> s = Class.forName("raylab.shading.Shading", true, Probe.class.getClassLoader());
            s.getField("mutant").setInt(null, body);
            return (Color) s.getMethod("shade", ShadingPoint.class, List.class).invoke(null, at, lights);
        }

        static Color color(SplittableRandom r, double hi) {
            return new Color(r.nextDouble(0, hi), r.nextDouble(0, hi), r.nextDouble(0, hi));
        }

        static Vec3 unit(SplittableRandom r) {
            while (true) {
                Vec3 v = new Vec3(r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1));
                double len = v.length();
                if (len > 0.1 && len <= 1) {
                    return v.normalize();
                }
            }
        }

        static boolean close(Color a, Color b) {
            double tol = 1e-9 * (1 + Math.abs(a.r) + Math.abs(a.g) + Math.abs(a.b));
            return Math.abs(a.r - b.r) <= tol && Math.abs(a.g - b.g) <= tol && Math.abs(a.b - b.b) <= tol
                    || !a.isFinite() && !b.isFinite();
        }

        /**
         * Seeded points of the course's materials (Lambertian, Blinn-Phong), the viewer anywhere
         * above the surface (often straight above), 0 to 4 lights anywhere (one in four exactly
         * at the point, on the horizon or straight behind), each blocked or not: the first where
         * body k and body 0 differ, described; or null.
         */
        public static String difference(int k, long seed, int trials) throws ReflectiveOperationException {
            SplittableRandom r = new SplittableRandom(seed);
            for (int i = 0; i < trials; i++) {
                boolean axis = r.nextInt(3) == 0; // exact horizons need an axis-aligned normal
                Vec3 x = axis ? new Vec3(1, 2, 3) : new Vec3(r.nextDouble(-5, 5), r.nextDouble(-5, 5), r.nextDouble(-5, 5));
                Vec3 n = axis ? new Vec3(0, 0, 1) : unit(r);
                Vec3 v = unit(r);
                v = r.nextInt(3) == 0 ? n : v.dot(n) < 0 ? v.negate() : v;
                Material m = r.nextBoolean() ? new Lambertian(color(r, 1), color(r, 1), "matte")
                        : new BlinnPhong(color(r, 1), color(r, 1), r.nextDouble(1, 100), color(r, 1), "glossy");
                Color ia = r.nextInt(4) == 0 ? Color.BLACK : color(r, 0.5);
                List<PointLight> lights = new ArrayList<>();
                Set<PointLight> blocked = new java.util.HashSet<>();
                int count = r.nextInt(5);
                for (int j = 0; j < count; j++) {
                    Vec3 q = switch (r.nextInt(8)) {
                        case 0 -> x;
                        case 1 -> axis ? x.plus(new Vec3(r.nextDouble(-3, 3), r.nextDouble(-3, 3), 0)) : x.plus(n.times(-2));
                        case 2 -> x.minus(n.times(r.nextDouble(0.5, 5)));
                        default -> x.plus(unit(r).times(r.nextDouble(0.5, 20)));
                    };
                    PointLight light = new PointLight(q, color(r, 1.5), true, "light " + j);
                    lights.add(light);
                    if (r.nextInt(3) == 0) {
                        blocked.add(light);
                    }
                }
                Vec3 nn = n;
                Vec3 vv = v;
                Color want = shade(0, ShadingPoint.plain(x, nn, vv, m, ia, l -> !blocked.contains(l)), lights);
                Color got = shade(k, ShadingPoint.plain(x, nn, vv, m, ia, l -> !blocked.contains(l)), lights);
                if (!close(want, got)) {
                    return "trial " + i + " (seed " + seed + "): " + m.getClass().getSimpleName() + ", n " + n + ", v " + v
                            + ", " + lights.size() + " light(s) " + lights.stream().map(l -> l.position.toString()).toList()
                            + ", blocked " + blocked.stream().map(l -> l.name).sorted().toList() + ": reference " + want
                            + ", mutant " + got;
                }
            }
            return null;
        }

        /** Renders the scene with the selected body; the comparison when it is outside the tolerance, else null. */
        public static String sceneDiffers(String scene, String reference, double tolerance) throws Exception {
            raylab.scene.Scene s = raylab.scene.SceneLoader.load(Path.of(scene));
            raylab.render.Image image = new raylab.render.Renderer(s).render(1, tile -> { });
            raylab.render.ImageCompare.Result c = raylab.render.ImageCompare.compare(image.toBufferedImage(),
                    raylab.render.PngFiles.read(Path.of(reference)));
            return c.matches(tolerance) ? null : c.summary();
        }
    }
}
