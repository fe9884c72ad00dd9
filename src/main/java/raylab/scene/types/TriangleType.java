package raylab.scene.types;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.scene.SceneException;
import raylab.scene.SurfaceType;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * The built-in triangle: {@code {"type": "triangle", "vertices": [a, b, c]}} in a scene, with
 * the vertices as {@code "a"}, {@code "b"}, {@code "c"} in a data case. A variant moves each
 * vertex; {@code raylab trace} says when the ray is parallel to its plane (n·d = 0).
 */
public final class TriangleType implements SurfaceType {
    @Override
    public String type() {
        return "triangle";
    }

    @Override
    public String description() {
        return "a triangle";
    }

    @Override
    public List<String> keys() {
        return List.of("type", "name", "vertices", "material");
    }

    @Override
    public List<String> requiredKeys() {
        return List.of("type", "vertices", "material");
    }

    /** Its entry under {@code $defs} of scenes/scene.schema.json: each key described and typed. */
    @Override
    public ObjectNode schema() {
        return SchemaJson.entry(this, "A triangle; its normal points to the side from which the vertices are seen"
                + " counter-clockwise.", "A single triangle.", """
                {
                  "vertices": {"description": "The vertices a, b, c.", "type": "array", "minItems": 3, "maxItems": 3,
                               "items": {%s}}
                }
                """.formatted(SchemaJson.POINT));
    }

    @Override
    public Surface build(Fields f, Material m, String name) throws SceneException {
        int n = f.count("vertices");
        if (n != 3) {
            throw f.fail("vertices", "expected 3 vertices [[x, y, z], [x, y, z], [x, y, z]], got " + n);
        }
        return new Triangle(f.vec3("vertices", 0), f.vec3("vertices", 1), f.vec3("vertices", 2), m, name);
    }

    @Override
    public void move(ObjectNode s, double[] d) {
        Moves.points(s, "vertices", d);
    }

    @Override
    public String caseProblem(JsonNode s) {
        return CaseJson.vec3Problem(s, "a", "b", "c");
    }

    @Override
    public Surface buildCase(JsonNode s, Material m) {
        return new Triangle(CaseJson.vec3(s.get("a")), CaseJson.vec3(s.get("b")), CaseJson.vec3(s.get("c")), m,
                "triangle");
    }

    @Override
    public String traceNote(Surface s, Ray ray) {
        if (!(s instanceof Triangle tr)) {
            return "";
        }
        Vec3 n = tr.b.minus(tr.a).cross(tr.c.minus(tr.a));
        if (n.dot(ray.d) != 0) {
            return "";
        }
        return n.dot(ray.p.minus(tr.a)) == 0 ? "; the ray lies in the triangle's plane (n·d = 0 and n·(p - a) = 0)"
                : "; the ray is parallel to the triangle's plane (n·d = 0)";
    }
}
