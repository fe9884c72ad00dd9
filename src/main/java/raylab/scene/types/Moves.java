package raylab.scene.types;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * How the built-in types move a surface's JSON for a graded scene's variant ({@code "placement"}),
 * as raylab.grade.SceneVariants moves cameras and lights.
 */
final class Moves {
    private Moves() {
    }

    /** {@code s.key += d}; a missing key counts as [0, 0, 0] (a mesh's translate). */
    static void point(ObjectNode s, String key, double[] d) {
        s.set(key, moved(s, s.get(key), d));
    }

    /** Every point of the array {@code s.key} moved by d. */
    static void points(ObjectNode s, String key, double[] d) {
        ArrayNode out = s.arrayNode();
        for (JsonNode v : s.get(key)) {
            out.add(moved(s, v, d));
        }
        s.set(key, out);
    }

    /** v + d, each coordinate rounded to 1e-6 (a variant's JSON stays short). */
    private static ArrayNode moved(ObjectNode s, JsonNode v, double[] d) {
        ArrayNode a = s.arrayNode();
        for (int i = 0; i < 3; i++) {
            a.add(Math.round(((v == null ? 0 : v.get(i).asDouble()) + d[i]) * 1e6) / 1e6);
        }
        return a;
    }
}
