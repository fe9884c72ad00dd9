package raylab.scene.types;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.scene.SceneException;
import raylab.scene.SurfaceType;
import raylab.surface.Sphere;
import raylab.surface.Surface;

/**
 * The built-in sphere: {@code {"type": "sphere", "center": [x, y, z], "radius": r}}, r > 0. A
 * variant moves its center; a data case gives center and radius as the scene does.
 */
public final class SphereType implements SurfaceType {
    @Override
    public String type() {
        return "sphere";
    }

    @Override
    public String description() {
        return "a sphere";
    }

    @Override
    public List<String> keys() {
        return List.of("type", "name", "center", "radius", "material");
    }

    @Override
    public List<String> requiredKeys() {
        return List.of("type", "center", "radius", "material");
    }

    /** Its entry under {@code $defs} of scenes/scene.schema.json: each key described and typed. */
    @Override
    public ObjectNode schema() {
        return SchemaJson.entry(this, "A sphere with centre c and radius r.", "A sphere.", """
                {
                  "center": {"description": "The centre c.", %s},
                  "radius": {"description": "The radius r (positive).", "type": "number", "exclusiveMinimum": 0}
                }
                """.formatted(SchemaJson.POINT));
    }

    @Override
    public Surface build(Fields f, Material m, String name) throws SceneException {
        return new Sphere(f.vec3("center"), f.positive("radius"), m, name);
    }

    @Override
    public void move(ObjectNode s, double[] d) {
        Moves.point(s, "center", d);
    }

    @Override
    public String traceRule(Surface s, Vec3 point, Vec3 normal) {
        if (s instanceof Sphere sp && normal != null && point != null && normal.dot(point.minus(sp.center)) < 0) {
            return "a sphere's normal points out of the sphere, (x - c)/R; this one points into it";
        }
        return null;
    }

    /** Outside when ‖eye − c‖ &gt; r (1 + margin). */
    @Override
    public Boolean eyeOutsideConvex(Surface s, Vec3 eye, double margin) {
        if (!(s instanceof Sphere sphere) || !s.isConvex()) {
            return null;
        }
        return eye.minus(sphere.center).length() > sphere.radius * (1 + margin);
    }

    @Override
    public String caseProblem(JsonNode s) {
        String p = CaseJson.vec3Problem(s, "center");
        if (p == null && (!s.path("radius").isNumber() || s.get("radius").asDouble() <= 0)) {
            p = "sphere \"radius\" must be a number > 0";
        }
        return p;
    }

    @Override
    public Surface buildCase(JsonNode s, Material m) {
        return new Sphere(CaseJson.vec3(s.get("center")), s.get("radius").asDouble(), m, "sphere");
    }
}
