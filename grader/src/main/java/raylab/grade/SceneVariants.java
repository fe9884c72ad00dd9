package raylab.grade;

import java.nio.charset.StandardCharsets;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Variants of a published scene: the camera, the lights and named surfaces moved within the
 * bounds of a {@link VariantSpec}, drawn from a seed. Deterministic: the same published scene,
 * spec and seed give the same JSON on every machine and JVM (its own SplitMix64 generator and
 * a fixed hash of the scene name, no {@code java.util.Random} or {@code hashCode}).
 *
 * <p>What each move keeps (the bounds in {@code assignment.json} are chosen so that it keeps
 * the scene's point; {@link VariantCheck} checks it):
 * <ul>
 * <li>a perspective eye orbits its look-at point: the look-at point, the up vector and so the
 *     scene's centre of interest stay; its elevation stays between 10° and 170° from up (a camera
 *     given by {@code viewDirection} orbits the point one unit ahead and keeps its form);</li>
 * <li>an orthographic view pans by whole pixels: every face that lay on a row or column of pixel
 *     centres still does (a {@code lookAt} point pans with the eye);</li>
 * <li>lights and surfaces move by per-axis offsets: an axis with bound 0 is never moved (an
 *     object on the floor stays on it, a lamp under a shelf keeps its height); an intensity
 *     written as one number stays one number.</li>
 * </ul>
 */
public final class SceneVariants {
    private SceneVariants() {
    }

    /** The seed of one scene's variant in a grading with seed {@code gradingSeed}. */
    public static long seedFor(long gradingSeed, String sceneName) {
        long h = 0xcbf29ce484222325L; // FNV-1a 64 of the UTF-8 name
        for (byte b : sceneName.getBytes(StandardCharsets.UTF_8)) {
            h ^= b & 0xff;
            h *= 0x100000001b3L;
        }
        return mix(gradingSeed ^ mix(h));
    }

    /**
     * The variant of {@code published} drawn from {@code seed} within {@code spec}; the published
     * JSON is not changed.
     */
    public static ObjectNode variant(JsonNode published, VariantSpec spec, long seed) {
        ObjectNode s = published.deepCopy();
        Draw r = new Draw(seed);
        ObjectNode cam = (ObjectNode) s.get("camera");
        // Every draw is made whatever its bound, so one part's spec never shifts another's values.
        double yaw = r.within(spec.yaw());
        double pitch = r.within(spec.pitch());
        double dist = r.within(spec.distance());
        double fov = r.within(spec.fov());
        // A pan of whole pixels other than none: one of the (2·pan + 1)² − 1 shifts, uniformly.
        int side = 2 * spec.pan() + 1;
        int cell = (int) (r.next() * (side * side - 1));
        cell = cell >= (side * side - 1) / 2 ? cell + 1 : cell; // skip the centre, (0, 0)
        long panX = cell % side - spec.pan();
        long panY = cell / side - spec.pan();
        if ("perspective".equals(cam.path("type").asText())) {
            orbit(cam, yaw, pitch, dist, fov);
        } else if (spec.pan() > 0) {
            pan(cam, s.path("image").path("height").asInt(), panX, panY);
        }
        for (JsonNode l : s.path("lights")) {
            double[] d = r.offset(spec.lightMove());
            double k = 1 + r.within(spec.intensity());
            ObjectNode light = (ObjectNode) l;
            light.set("position", vec(add(vec(light.get("position")), d)));
            JsonNode i = light.get("intensity");
            if (i.isNumber()) { // one number g: the gray [g, g, g], kept in that form
                light.put("intensity", round(i.asDouble() * k));
            } else {
                double[] c = vec(i);
                light.set("intensity", vec(new double[] {c[0] * k, c[1] * k, c[2] * k}));
            }
        }
        for (VariantSpec.Group g : spec.groups()) {
            double[] d = r.offset(g.move());
            for (JsonNode sn : s.path("surfaces")) {
                String name = sn.path("name").asText(null); // an unnamed surface is in no group
                if (name != null && g.objects().contains(name)) {
                    move((ObjectNode) sn, d);
                }
            }
        }
        return s;
    }

    private static void orbit(ObjectNode cam, double yawDeg, double pitchDeg, double dist, double fovDeg) {
        double[] eye = vec(cam.get("eye"));
        // A camera given by viewDirection orbits the point one unit ahead along it and keeps that
        // form: the variant has the same keys as the published scene.
        boolean byDirection = !cam.has("lookAt");
        double[] at = byDirection ? add(eye, unit(vec(cam.get("viewDirection")))) : vec(cam.get("lookAt"));
        double[] up = unit(cam.has("up") ? vec(cam.get("up")) : new double[] {0, 1, 0});
        double[] v = sub(eye, at);
        double r = len(v);
        double along = dot(v, up);
        double[] h = sub(v, scale(up, along));
        if (len(h) > 1e-9 * r) {
            double[] hu = unit(h);
            double[] side = cross(up, hu);
            double a = Math.toRadians(yawDeg);
            double[] hRot = add(scale(hu, Math.cos(a)), scale(side, Math.sin(a)));
            double theta = Math.acos(Math.max(-1, Math.min(1, along / r)));
            double t = Math.max(Math.toRadians(10), Math.min(Math.toRadians(170), theta - Math.toRadians(pitchDeg)));
            v = add(scale(hRot, Math.sin(t)), scale(up, Math.cos(t)));
        } else {
            v = scale(v, 1 / r); // looking along up: no orbit about it
        }
        double[] moved = add(at, scale(v, r * (1 + dist)));
        cam.set("eye", vec(moved));
        if (byDirection) {
            cam.set("viewDirection", vec(sub(at, moved)));
        }
        double fov = cam.path("fov").asDouble(60);
        cam.put("fov", round(Math.max(5, Math.min(120, fov + fovDeg))));
    }

    /** Shifts an orthographic view by whole pixels along the image's right and up directions. */
    private static void pan(ObjectNode cam, int heightPixels, long px, long py) {
        double pixel = cam.path("viewHeight").asDouble() / heightPixels;
        double[] eye = vec(cam.get("eye"));
        boolean byPoint = cam.has("lookAt"); // then the look-at point pans with the eye
        double[] d = unit(byPoint ? sub(vec(cam.get("lookAt")), eye) : vec(cam.get("viewDirection")));
        double[] up = vec(cam.get("up"));
        double[] right = unit(cross(d, up));
        double[] trueUp = unit(cross(right, d));
        // No rounding here: whole pixels along axis-aligned directions are exact already.
        double[] shift = add(scale(right, px * pixel), scale(trueUp, py * pixel));
        cam.set("eye", exact(add(eye, shift)));
        if (byPoint) {
            cam.set("lookAt", exact(add(vec(cam.get("lookAt")), shift)));
        }
    }

    private static ArrayNode exact(double[] v) {
        ArrayNode a = com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.arrayNode();
        for (double c : v) {
            a.add(c);
        }
        return a;
    }

    /** Moves a surface as its type says ({@link raylab.scene.SurfaceType#move}). */
    private static void move(ObjectNode s, double[] d) {
        raylab.scene.SurfaceType t = raylab.scene.SurfaceTypes.all().get(s.path("type").asText());
        if (t == null) {
            throw new IllegalArgumentException("cannot move a surface of type " + s.path("type").asText());
        }
        t.move(s, d);
    }

    /** SplitMix64 (Steele, Lea and Flood 2014): the generator and its finalizer. */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    private static final class Draw {
        private long state;

        Draw(long seed) {
            state = seed;
        }

        /** Uniform in [0, 1). */
        double next() {
            state += 0x9e3779b97f4a7c15L;
            return (mix(state) >>> 11) * 0x1.0p-53;
        }

        /** Uniform in [−bound, bound]. */
        double within(double bound) {
            return (2 * next() - 1) * bound;
        }

        double[] offset(double[] bound) {
            return new double[] {within(bound[0]), within(bound[1]), within(bound[2])};
        }
    }

    private static double round(double d) {
        return Math.round(d * 1e6) / 1e6;
    }

    private static double[] vec(JsonNode n) {
        return new double[] {n.get(0).asDouble(), n.get(1).asDouble(), n.get(2).asDouble()};
    }

    private static ArrayNode vec(double[] v) {
        ArrayNode a = com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.arrayNode();
        for (double c : v) {
            a.add(round(c));
        }
        return a;
    }

    private static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double[] scale(double[] a, double k) {
        return new double[] {a[0] * k, a[1] * k, a[2] * k};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double len(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    private static double[] unit(double[] a) {
        return scale(a, 1 / len(a));
    }
}
