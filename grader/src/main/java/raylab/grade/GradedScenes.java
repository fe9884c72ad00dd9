package raylab.grade;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.course.Assignment;
import raylab.render.Renderer;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;

/**
 * The scenes a grading scores: for each graded scene with a {@code "variant"} spec, a variant
 * drawn from the grading's seed that keeps the scene's point ({@link VariantCheck}), and its
 * reference rendered by the reference solution in this (trusted) process, never written to disk.
 * Scenes without a spec are graded as published.
 *
 * <p>The hook for the grader: {@link #forGrading} before any student code runs; then the child
 * renders {@link Graded#json()} (written in place of the published scene in its copy of
 * {@code scenes/}, so meshes resolve as before) and the grader compares with
 * {@link Graded#reference()}.
 */
public final class GradedScenes {
    /** Variants drawn per scene before the published scene is graded instead (with a note). */
    static final int ATTEMPTS = 8;
    private static final ObjectMapper JSON = new ObjectMapper();

    private GradedScenes() {
    }

    /**
     * One graded scene of one grading.
     *
     * @param scene     the scene as assignment.json lists it
     * @param varied    whether this is a variant (false: the published scene)
     * @param seed      the scene's variant seed ({@link SceneVariants#seedFor}), attempt included
     * @param attempt   which draw kept the point (0 = the first)
     * @param json      the scene the student's code renders
     * @param reference the reference solution's PNG of {@code json}, or null for a published
     *                  scene (its reference PNG is on disk)
     * @param note      what the grading report says about it ("" for none)
     */
    public record Graded(Assignment.GradedScene scene, boolean varied, long seed, int attempt, String json,
            byte[] reference, String note) {
    }

    /** A fresh grading seed, in [0, 2^53) so that every JSON reader keeps it exactly. */
    public static long freshSeed() {
        return new SecureRandom().nextLong() & ((1L << 53) - 1);
    }

    /** The seed of attempt {@code k} of a scene: attempt 0 is {@link SceneVariants#seedFor} itself. */
    static long attemptSeed(long sceneSeed, int k) {
        return k == 0 ? sceneSeed : SceneVariants.mix(sceneSeed + k);
    }

    /**
     * Every graded scene of the milestones, varied and checked, with the references of the
     * variants rendered here.
     *
     * @throws IOException with a one-line message (file, JSON path) for a bad variant spec
     */
    public static List<Graded> forGrading(Path root, List<Assignment> milestones, long gradingSeed) throws IOException {
        return forGrading(root, milestones, gradingSeed, true);
    }

    /**
     * As {@link #forGrading(Path, List, long)}; with {@code render} false the variants' references
     * are left null (the grader has them from its render, or renders them with
     * {@link #renderReference} when it needs them).
     */
    public static List<Graded> forGrading(Path root, List<Assignment> milestones, long gradingSeed, boolean render)
            throws IOException {
        List<Graded> out = new ArrayList<>();
        for (Assignment a : milestones) {
            for (int i = 0; i < a.scenes().size(); i++) {
                out.add(forGrading(root, a, i, gradingSeed, render));
            }
        }
        return out;
    }

    /**
     * Scene {@code index} of milestone {@code a} in a grading with {@code gradingSeed}.
     *
     * @param render whether to render the variant's reference (false: only its JSON and check)
     */
    public static Graded forGrading(Path root, Assignment a, int index, long gradingSeed, boolean render)
            throws IOException {
        Assignment.GradedScene sc = a.scenes().get(index);
        Path file = root.resolve(sc.scene());
        JsonNode published = readScene(file);
        VariantSpec spec = spec(a, index, published);
        if (spec == null) {
            return new Graded(sc, false, 0, 0, JSON.writeValueAsString(published), null, "");
        }
        long base = SceneVariants.seedFor(gradingSeed, name(sc));
        try {
            VariantCheck.Profile pub = VariantCheck.analyze(published, file);
            List<String> lights = new ArrayList<>();
            published.path("lights").forEach(l -> lights.add(l.path("name").asText("light")));
            List<String> last = List.of();
            for (int k = 0; k < ATTEMPTS; k++) {
                long seed = attemptSeed(base, k);
                ObjectNode v = SceneVariants.variant(published, spec, seed);
                last = VariantCheck.problems(pub, VariantCheck.analyze(v, file), spec.coverage(), lights);
                if (last.isEmpty()) {
                    String text = JSON.writerWithDefaultPrettyPrinter().writeValueAsString(v) + "\n";
                    byte[] ref = render ? renderReference(text, file) : null;
                    return new Graded(sc, true, seed, k, text, ref,
                            k == 0 ? "" : sc.scene() + GradeReport.REDRAWN_NOTE + (k + 1) + " times to keep its point");
                }
            }
            return new Graded(sc, false, 0, 0, JSON.writeValueAsString(published), null, sc.scene()
                    + GradeReport.PUBLISHED_NOTE + "no variant of " + ATTEMPTS + " kept its point (last: " + last.get(0)
                    + "); narrow its \"variant\" bounds");
        } catch (SceneException e) {
            throw new IOException(sc.scene() + ": a variant does not load: " + e.getMessage());
        }
    }

    /** The scene's name for its seed: its file name without {@code .json}. */
    static String name(Assignment.GradedScene sc) {
        String f = Path.of(sc.scene()).getFileName().toString();
        return f.endsWith(".json") ? f.substring(0, f.length() - 5) : f;
    }

    /**
     * Reads and checks every graded scene's variant spec of the milestones.
     *
     * @throws IOException "assignments/NN-id/assignment.json: scenes[i].variant...: what is wrong"
     */
    public static void validate(Path root, List<Assignment> milestones) throws IOException {
        for (Assignment a : milestones) {
            for (int i = 0; i < a.scenes().size(); i++) {
                spec(a, i, readScene(root.resolve(a.scenes().get(i).scene())));
            }
        }
    }

    /** The spec of scene {@code index}, or null for none. */
    static VariantSpec spec(Assignment a, int index, JsonNode published) throws IOException {
        JsonNode v = a.scenes().get(index).variant();
        if (v == null || v.isNull()) {
            return null;
        }
        try {
            return VariantSpec.parse(v, "scenes[" + index + "].variant", published);
        } catch (VariantSpec.Invalid e) {
            throw new IOException(a.folder() + "/assignment.json: " + e.getMessage());
        }
    }

    private static JsonNode readScene(Path file) throws IOException {
        try {
            JsonNode n = JSON.readTree(file.toFile());
            SceneLoader.parse(n.toString(), file); // a scene that does not load cannot be varied
            return n;
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IOException(file + ": not valid JSON: " + e.getOriginalMessage().split("\n")[0]);
        } catch (SceneException e) {
            throw new IOException(e.getMessage());
        }
    }

    /** The reference solution's PNG of a scene (JSON text as if read from {@code file}), rendered in this process. */
    public static byte[] renderReference(String json, Path file) throws IOException {
        try {
            Renderer r = new Renderer(SceneLoader.parse(json, file));
            ByteArrayOutputStream b = new ByteArrayOutputStream();
            ImageIO.write(r.render(2, null).toBufferedImage(), "png", b);
            return b.toByteArray();
        } catch (SceneException e) {
            throw new IOException(e.getMessage());
        }
    }
}
