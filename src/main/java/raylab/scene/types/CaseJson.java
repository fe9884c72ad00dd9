package raylab.scene.types;

import com.fasterxml.jackson.databind.JsonNode;

import raylab.math.Vec3;

/** The values of a data case (the grader's README, "Data cases"), as the built-in types read them. */
public final class CaseJson {
    private CaseJson() {
    }

    /** The problem with {@code parent.field} as {@code [x, y, z]}, or null if it is one. */
    public static String vec3Problem(JsonNode parent, String field) {
        JsonNode v = parent.get(field);
        if (v == null || !v.isArray() || v.size() != 3 || !v.get(0).isNumber() || !v.get(1).isNumber()
                || !v.get(2).isNumber()) {
            return "\"" + field + "\" must be an array of 3 numbers";
        }
        return null;
    }

    /** The first problem of {@link #vec3Problem} among the fields, or null. */
    public static String vec3Problem(JsonNode parent, String... fields) {
        for (String f : fields) {
            String p = vec3Problem(parent, f);
            if (p != null) {
                return p;
            }
        }
        return null;
    }

    /** {@code [x, y, z]}, checked already. */
    public static Vec3 vec3(JsonNode a) {
        return new Vec3(a.get(0).asDouble(), a.get(1).asDouble(), a.get(2).asDouble());
    }
}
