package raylab.grade;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * How far a graded scene's variants may move from the published scene: the {@code "variant"}
 * object of a graded scene in {@code assignment.json} (format in docs/assignment-format.md).
 * Every amount is a bound: each variant draws its own value uniformly within ±bound.
 *
 * @param yaw       perspective camera: degrees the eye orbits the look-at point about the up axis
 * @param pitch     perspective camera: degrees the eye rises or sinks around the look-at point
 * @param distance  perspective camera: fraction the eye's distance to the look-at point changes
 * @param fov       perspective camera: degrees added to the field of view
 * @param pan       orthographic camera: whole pixels the view shifts sideways and up (pixel
 *                  centres stay where they were relative to the scene's pixel grid)
 * @param lightMove per axis, how far each light moves (scene units)
 * @param intensity fraction each light's intensity changes (one factor per light, all channels)
 * @param groups    surfaces moved together, each group by its own offset
 * @param coverage  the factor within which each surface's share of the image, and the shadowed
 *                  and highlighted shares, must stay of the published scene's
 */
public record VariantSpec(double yaw, double pitch, double distance, double fov, int pan, double[] lightMove,
        double intensity, List<Group> groups, double coverage) {

    /** Bounds of the bounds: larger moves than these change what a scene shows. */
    static final double MAX_YAW = 45, MAX_PITCH = 30, MAX_DISTANCE = 0.5, MAX_FOV = 15, MAX_INTENSITY = 0.5;
    static final int MAX_PAN = 32;
    static final double DEFAULT_COVERAGE = 2;

    /**
     * Surfaces that move by one shared offset.
     *
     * @param objects surface names of the published scene
     * @param move    per axis, the bound of the offset (scene units)
     */
    public record Group(List<String> objects, double[] move) {
    }

    /** A bad spec, with the JSON path inside the assignment file. */
    public static final class Invalid extends Exception {
        private static final long serialVersionUID = 1L;

        Invalid(String path, String message) {
            super(path + ": " + message);
        }
    }

    private static final Map<String, Set<String>> KEYS = Map.of(
            "", Set.of("camera", "lights", "placement", "coverage"),
            "camera", Set.of("yaw", "pitch", "distance", "fov", "pan"),
            "lights", Set.of("move", "intensity"),
            "placement[]", Set.of("objects", "move"));

    /**
     * Reads and checks a spec against the published scene it varies.
     *
     * @param n     the {@code "variant"} object
     * @param path  its JSON path, such as {@code scenes[1].variant}, for messages
     * @param scene the published scene's JSON (camera type, surface names, lights)
     */
    public static VariantSpec parse(JsonNode n, String path, JsonNode scene) throws Invalid {
        object(n, path, "");
        String cameraType = scene.path("camera").path("type").asText("");
        double yaw = 0, pitch = 0, distance = 0, fov = 0;
        int pan = 0;
        JsonNode cam = n.get("camera");
        if (cam != null) {
            String p = path + ".camera";
            object(cam, p, "camera");
            boolean perspective = cameraType.equals("perspective");
            for (String k : List.of("yaw", "pitch", "distance", "fov")) {
                if (cam.has(k) && !perspective) {
                    throw new Invalid(p + "." + k, "only a perspective camera orbits; this scene's camera is "
                            + cameraType + " (use pan)");
                }
            }
            if (cam.has("pan") && !cameraType.equals("orthographic")) {
                throw new Invalid(p + ".pan", "only an orthographic camera pans by whole pixels; this scene's camera is "
                        + cameraType + " (use yaw, pitch, distance, fov)");
            }
            yaw = number(cam, "yaw", p, 0, MAX_YAW);
            pitch = number(cam, "pitch", p, 0, MAX_PITCH);
            distance = number(cam, "distance", p, 0, MAX_DISTANCE);
            fov = number(cam, "fov", p, 0, MAX_FOV);
            if (cam.has("pan")) {
                JsonNode v = cam.get("pan");
                if (!v.isIntegralNumber() || v.asInt() < 0 || v.asInt() > MAX_PAN) {
                    throw new Invalid(p + ".pan", "must be a whole number of pixels from 0 to " + MAX_PAN + ", got " + v);
                }
                pan = v.asInt();
            }
        }
        double[] lightMove = {0, 0, 0};
        double intensity = 0;
        JsonNode lights = n.get("lights");
        if (lights != null) {
            String p = path + ".lights";
            object(lights, p, "lights");
            if (!scene.path("lights").isArray() || scene.path("lights").isEmpty()) {
                throw new Invalid(p, "the scene has no lights to vary");
            }
            if (lights.has("move")) {
                lightMove = vector(lights.get("move"), p + ".move");
            }
            intensity = number(lights, "intensity", p, 0, MAX_INTENSITY);
        }
        List<Group> groups = new ArrayList<>();
        JsonNode placement = n.get("placement");
        if (placement != null) {
            String p = path + ".placement";
            if (!placement.isArray()) {
                throw new Invalid(p, "must be an array of {\"objects\": [names], \"move\": [dx, dy, dz]}");
            }
            Set<String> names = new HashSet<>();
            for (JsonNode s : scene.path("surfaces")) {
                names.add(s.path("name").asText(null));
            }
            Set<String> placed = new HashSet<>();
            for (int i = 0; i < placement.size(); i++) {
                String gp = p + "[" + i + "]";
                JsonNode g = placement.get(i);
                object(g, gp, "placement[]");
                JsonNode objects = g.get("objects");
                if (objects == null || !objects.isArray() || objects.isEmpty()) {
                    throw new Invalid(gp + ".objects", "must be a non-empty array of surface names");
                }
                List<String> list = new ArrayList<>();
                for (int j = 0; j < objects.size(); j++) {
                    JsonNode o = objects.get(j);
                    String op = gp + ".objects[" + j + "]";
                    if (!o.isTextual()) {
                        throw new Invalid(op, "must be a surface name (a string), got " + o);
                    }
                    if (!names.contains(o.asText())) {
                        throw new Invalid(op, "the scene has no surface named \"" + o.asText() + "\"");
                    }
                    if (!placed.add(o.asText())) {
                        throw new Invalid(op, "\"" + o.asText() + "\" is already placed by another group");
                    }
                    list.add(o.asText());
                }
                if (!g.has("move")) {
                    throw new Invalid(gp, "missing \"move\": [dx, dy, dz]");
                }
                groups.add(new Group(List.copyOf(list), vector(g.get("move"), gp + ".move")));
            }
        }
        double coverage = n.has("coverage") ? number(n, "coverage", path, 1.1, 10) : DEFAULT_COVERAGE;
        if (cam == null && lights == null && groups.isEmpty()) {
            throw new Invalid(path, "varies nothing: give camera, lights or placement");
        }
        return new VariantSpec(yaw, pitch, distance, fov, pan, lightMove, intensity, List.copyOf(groups), coverage);
    }

    private static void object(JsonNode n, String path, String kind) throws Invalid {
        if (!n.isObject()) {
            throw new Invalid(path, "must be an object, got " + n.getNodeType().name().toLowerCase());
        }
        Set<String> allowed = KEYS.get(kind);
        for (Iterator<String> it = n.fieldNames(); it.hasNext();) {
            String k = it.next();
            if (!allowed.contains(k)) {
                throw new Invalid(path + "." + k, "unknown field (allowed: " + String.join(", ", allowed.stream().sorted().toList()) + ")");
            }
        }
    }

    private static double number(JsonNode parent, String key, String path, double min, double max) throws Invalid {
        JsonNode v = parent.get(key);
        if (v == null) {
            return 0;
        }
        if (!v.isNumber() || !Double.isFinite(v.asDouble()) || v.asDouble() < min || v.asDouble() > max) {
            throw new Invalid(path + "." + key, "must be a number from " + fmt(min) + " to " + fmt(max) + ", got " + v);
        }
        return v.asDouble();
    }

    private static double[] vector(JsonNode v, String path) throws Invalid {
        if (!v.isArray() || v.size() != 3) {
            throw new Invalid(path, "must be [dx, dy, dz], three numbers >= 0, got " + v);
        }
        double[] out = new double[3];
        for (int i = 0; i < 3; i++) {
            JsonNode c = v.get(i);
            if (!c.isNumber() || !Double.isFinite(c.asDouble()) || c.asDouble() < 0) {
                throw new Invalid(path + "[" + i + "]", "must be a number >= 0 (a bound: the move is drawn within ±it), got " + c);
            }
            out[i] = c.asDouble();
        }
        return out;
    }

    private static String fmt(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }
}
