package raylab.cases;

import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.testing.Check;
import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Runs one data-driven case (a JSON object from an assignment's cases/ folder, format in the
 * grader's README): builds the surface and the ray, intersects, and compares with the expected
 * hit or miss. The grader generates one JUnit test per case that calls {@link #check}.
 */
public final class CaseCheck {
    private static final ObjectMapper JSON = new ObjectMapper();

    private CaseCheck() {
    }

    public static void check(String caseJson) throws Exception {
        JsonNode c = JSON.readTree(caseJson);
        Surface s = surface(c.get("surface"));
        JsonNode r = c.get("ray");
        Ray ray = new Ray(vec(r.get("p")), vec(r.get("d")), num(r.get("tMin"), 0),
                num(r.get("tMax"), Double.POSITIVE_INFINITY));
        IntersectionRecord rec = new IntersectionRecord();
        JsonNode prior = c.get("recordT");
        if (prior != null && !prior.isNull()) {
            rec.t = prior.asDouble();
        }
        double before = rec.t;
        boolean hit = Check.intersect(s, rec, ray);
        JsonNode e = c.get("expect");
        double tol = num(e.get("tolerance"), 1e-6);
        String ctx = "\n  case:     " + c.path("name").asText() + "\n  surface:  " + Check.describe(s)
                + "\n  ray:      " + Check.describe(ray)
                + (c.hasNonNull("hint") ? "\nHINT: " + c.get("hint").asText() : "");
        if (!e.path("hit").asBoolean()) {
            if (hit || rec.t != before || rec.surface != null) {
                fail("expected no hit, but intersect returned " + hit + " and the record is: " + rec + ctx);
            }
            // Scored with a control hit through the surface's centre: a constant miss earns nothing.
            Check.controlHit(s);
            return;
        }
        if (!hit) {
            String why = ctx;
            if (s instanceof Triangle tri && e.has("point")) {
                // Evidence for the case's hint (about its edge or vertex): the same ray moved to
                // pass through the centroid. If that misses too, the mistake is elsewhere.
                Vec3 centroid = tri.a.plus(tri.b).plus(tri.c).times(1.0 / 3);
                Ray probe = new Ray(ray.p.plus(centroid.minus(vec(e.get("point")))), ray.d, ray.tMin, ray.tMax);
                if (!Check.intersect(s, new IntersectionRecord(), probe)) {
                    String edge = Check.edgeHint(tri, centroid);
                    why = "\n  case:     " + c.path("name").asText() + "\n  surface:  " + Check.describe(s)
                            + "\n  ray:      " + Check.describe(ray)
                            + "\n  the same ray moved to pass through the centroid " + centroid + " misses too"
                            + (edge == null ? "" : "\nHINT: " + edge);
                }
            }
            fail("expected a hit" + (e.has("t") ? " at t = " + e.get("t").asDouble() : "")
                    + " but intersect returned false" + why);
        }
        if (e.has("t") && !(Math.abs(rec.t - e.get("t").asDouble()) <= tol * Math.max(1, Math.abs(e.get("t").asDouble())))) {
            fail("expected t = " + e.get("t").asDouble() + " but the record has t = " + rec.t + ctx);
        }
        if (e.has("point")) {
            Vec3 p = vec(e.get("point"));
            if (rec.point == null || !(rec.point.minus(p).length() <= tol * Math.max(1, p.maxAbs()))) {
                fail("expected the hit point " + p + " but the record has " + rec.point + ctx);
            }
        }
        if (e.has("normal")) {
            Vec3 n = vec(e.get("normal"));
            if (rec.normal == null || !(rec.normal.minus(n).length() <= Math.max(tol, 1e-9))) {
                fail("expected the unit normal " + n + " but the record has " + rec.normal + ctx);
            }
        }
        if (rec.surface != s) {
            fail("the record should name the surface that was hit, but names "
                    + (rec.surface == null ? "none" : Check.describe(rec.surface)) + ctx);
        }
    }

    /** The case's surface, built as its type says (raylab.scene.SurfaceType.buildCase). */
    static Surface surface(JsonNode s) {
        raylab.scene.SurfaceType type = raylab.scene.SurfaceTypes.all().get(s.path("type").asText());
        if (type == null || !type.inDataCases()) {
            throw new IllegalArgumentException("unknown surface type '" + s.path("type").asText() + "'");
        }
        try {
            return type.buildCase(s, new FlatColor(Color.WHITE, "white"));
        } catch (raylab.scene.SceneException e) {
            throw new IllegalArgumentException(e.getMessage());
        }
    }

    static Vec3 vec(JsonNode a) {
        return new Vec3(a.get(0).asDouble(), a.get(1).asDouble(), a.get(2).asDouble());
    }

    static double num(JsonNode n, double dflt) {
        return n == null || n.isNull() ? dflt : n.asDouble();
    }
}
