package raylab.grade;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.scene.SceneException;

/**
 * A graded scene's {@code "variant"} for {@code raylab assignment add-scene} (instructors): a
 * default spec made from what the scene contains, and the check that a spec keeps the scene's
 * point, the grader's own ({@link SceneVariants#variant}, {@link VariantCheck#problems}) on the
 * first draw of every one of several grading seeds, as {@code VariantPointTest} checks the
 * bundled scenes.
 *
 * <p>The default: a perspective camera given by {@code lookAt} orbits by ±15° of yaw and ±6° of
 * pitch and moves ±10 % closer or farther; an orthographic one given by {@code viewDirection}
 * pans by up to 6 whole pixels (other cameras stay); lights, when there are,
 * move by up to a tenth of the camera's distance to its look-at point sideways (a twentieth up
 * and down) and change intensity by ±15 %. Surfaces never move: which ones rest on others is the
 * scene's own knowledge ({@code "placement"} by hand, docs/assignment-format.md).
 */
public final class VariantProposal {
    private static final ObjectMapper JSON = new ObjectMapper();

    private VariantProposal() {
    }

    /** The default spec of a published scene (JSON as in assignment.json). */
    public static ObjectNode defaultSpec(JsonNode scene) {
        ObjectNode spec = JSON.createObjectNode();
        JsonNode camera = scene.path("camera");
        // The grader orbits a perspective camera about its lookAt and pans an orthographic one
        // along its viewDirection (SceneVariants): a camera given the other way stays.
        if (camera.path("type").asText("perspective").equals("orthographic")) {
            if (camera.has("viewDirection")) {
                spec.putObject("camera").put("pan", 6);
            }
        } else if (camera.has("lookAt")) {
            spec.putObject("camera").put("yaw", 15).put("pitch", 6).put("distance", 0.1);
        }
        if (scene.path("lights").size() > 0) {
            double d = distance(camera);
            double side = round2(0.1 * d);
            double up = round2(0.05 * d);
            ObjectNode l = spec.putObject("lights");
            l.putArray("move").add(side).add(up).add(side);
            l.put("intensity", 0.15);
        }
        return spec;
    }

    /** The spec with every bound halved (a narrower try when the default loses the point). */
    public static ObjectNode narrower(ObjectNode spec) {
        ObjectNode out = spec.deepCopy();
        if (out.get("camera") instanceof ObjectNode c) {
            for (String k : List.of("yaw", "pitch", "distance", "fov")) {
                if (c.has(k)) {
                    c.put(k, round2(c.get(k).asDouble() / 2));
                }
            }
            if (c.has("pan")) {
                c.put("pan", Math.max(1, c.get("pan").asInt() / 2));
            }
        }
        if (out.get("lights") instanceof ObjectNode l) {
            if (l.get("move") instanceof com.fasterxml.jackson.databind.node.ArrayNode m) {
                for (int i = 0; i < m.size(); i++) {
                    m.set(i, JSON.getNodeFactory().numberNode(round2(m.get(i).asDouble() / 2)));
                }
            }
            if (l.has("intensity")) {
                l.put("intensity", round2(l.get("intensity").asDouble() / 2));
            }
        }
        return out;
    }

    /** The first draws that lose the point, one line each ("seed N: what it lost"); empty when all keep it. */
    public record Checked(List<Long> seeds, List<String> failures) {
        public boolean keepsThePoint() {
            return failures.isEmpty();
        }
    }

    /**
     * Checks a spec as the grader would, on the first draw of {@code seeds} grading seeds drawn
     * from {@code seed0}.
     *
     * @param name the scene's name for its seed (file name without {@code .json})
     * @throws VariantSpec.Invalid for a bad spec ("variant.lights.move[1]: ...")
     */
    public static Checked check(JsonNode published, Path file, JsonNode spec, String name, int seeds, long seed0)
            throws VariantSpec.Invalid, SceneException {
        VariantSpec s = VariantSpec.parse(spec, "variant", published);
        VariantCheck.Profile pub = VariantCheck.analyze(published, file);
        List<String> lights = new ArrayList<>();
        published.path("lights").forEach(l -> lights.add(l.path("name").asText("light")));
        SplittableRandom r = new SplittableRandom(seed0);
        List<Long> used = new ArrayList<>();
        List<String> failures = new ArrayList<>();
        for (int k = 0; k < seeds; k++) {
            long seed = r.nextLong() & ((1L << 53) - 1);
            used.add(seed);
            ObjectNode v = SceneVariants.variant(published, s, SceneVariants.seedFor(seed, name));
            List<String> p = VariantCheck.problems(pub, VariantCheck.analyze(v, file), s.coverage(), lights);
            if (!p.isEmpty()) {
                failures.add("grading seed " + seed + ": " + String.join("; ", p));
            }
        }
        return new Checked(List.copyOf(used), List.copyOf(failures));
    }

    private static double distance(JsonNode camera) {
        JsonNode eye = camera.path("eye");
        JsonNode at = camera.path("lookAt");
        if (eye.size() == 3 && at.size() == 3) {
            double dx = eye.get(0).asDouble() - at.get(0).asDouble();
            double dy = eye.get(1).asDouble() - at.get(1).asDouble();
            double dz = eye.get(2).asDouble() - at.get(2).asDouble();
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (d > 0 && Double.isFinite(d)) {
                return d;
            }
        }
        return 1;
    }

    /** Two significant digits: 0.7, 0.035, 1.2. */
    static double round2(double v) {
        if (v == 0 || !Double.isFinite(v)) {
            return 0;
        }
        return new java.math.BigDecimal(v).round(new java.math.MathContext(2)).doubleValue();
    }

    /** A spec as one line of JSON (as assignment.json keeps it). */
    public static String text(JsonNode spec) {
        try {
            return JSON.writeValueAsString(spec);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }
}
