package raylab.scene.types;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.scene.Display;
import raylab.scene.SceneException;
import raylab.scene.SurfaceType;
import raylab.surface.Box;
import raylab.surface.Surface;

/**
 * The built-in axis-aligned box: {@code {"type": "box", "min": [x, y, z], "max": [x, y, z]}},
 * min ≤ max in every axis. A variant moves both corners; {@code raylab trace} says when a ray
 * parallel to a slab lies on a face's plane or outside the slab.
 */
public final class BoxType implements SurfaceType {
    private static final String[] AXIS = {"x", "y", "z"};

    @Override
    public String type() {
        return "box";
    }

    @Override
    public String description() {
        return "a box";
    }

    @Override
    public List<String> keys() {
        return List.of("type", "name", "min", "max", "material");
    }

    @Override
    public List<String> requiredKeys() {
        return List.of("type", "min", "max", "material");
    }

    /** Its entry under {@code $defs} of scenes/scene.schema.json: each key described and typed. */
    @Override
    public ObjectNode schema() {
        return SchemaJson.entry(this, "An axis-aligned box between the corners min and max.", "An axis-aligned box.", """
                {
                  "min": {"description": "The corner with the smallest coordinates.", %1$s},
                  "max": {"description": "The corner with the largest coordinates (at least min in every axis).", %1$s}
                }
                """.formatted(SchemaJson.POINT));
    }

    @Override
    public Surface build(Fields f, Material m, String name) throws SceneException {
        Vec3 min = f.vec3("min");
        Vec3 max = f.vec3("max");
        for (int axis = 0; axis < 3; axis++) {
            if (min.get(axis) > max.get(axis)) {
                String c = AXIS[axis];
                throw f.fail("max", "max." + c + " = " + Display.number(max.get(axis))
                        + " is less than min." + c + " = " + Display.number(min.get(axis))
                        + "; a box needs min <= max in every axis");
            }
        }
        return new Box(min, max, m, name);
    }

    @Override
    public void move(ObjectNode s, double[] d) {
        Moves.point(s, "min", d);
        Moves.point(s, "max", d);
    }

    /** Outside when the eye is beyond a slab by margin times the box's size (or its distance from 0). */
    @Override
    public Boolean eyeOutsideConvex(Surface s, Vec3 eye, double margin) {
        if (!(s instanceof Box box) || !s.isConvex()) {
            return null;
        }
        double size = box.max.minus(box.min).maxAbs();
        double m = margin * Math.max(size, box.min.maxAbs() + box.max.maxAbs());
        for (int axis = 0; axis < 3; axis++) {
            double e = eye.get(axis);
            if (e < box.min.get(axis) - m || e > box.max.get(axis) + m) {
                return true;
            }
        }
        return false;
    }

    @Override
    public String caseProblem(JsonNode s) {
        return CaseJson.vec3Problem(s, "min", "max");
    }

    @Override
    public Surface buildCase(JsonNode s, Material m) {
        return new Box(CaseJson.vec3(s.get("min")), CaseJson.vec3(s.get("max")), m, "box");
    }

    /** "; the ray lies in the plane x = 1 of a face (a slab with d.x = 0)" and the like, or "". */
    @Override
    public String traceNote(Surface s, Ray ray) {
        if (!(s instanceof Box b)) {
            return "";
        }
        StringBuilder note = new StringBuilder();
        for (int i = 0; i < 3; i++) {
            if (ray.d.get(i) != 0) {
                continue;
            }
            double p = ray.p.get(i);
            String n = AXIS[i];
            if (p == b.min.get(i) || p == b.max.get(i)) {
                note.append("; the ray lies in the plane ").append(n).append(" = ").append(Display.traced(p))
                        .append(" of a face: in the slab of ").append(n).append(", d.").append(n)
                        .append(" = 0 and p.").append(n).append(" is on its boundary (0/0 = NaN)");
            } else if (p < b.min.get(i) || p > b.max.get(i)) {
                note.append("; d.").append(n).append(" = 0 and p.").append(n).append(" = ")
                        .append(Display.traced(p)).append(" lies outside the slab of ").append(n)
                        .append(": the ray never enters it");
            }
        }
        return note.toString();
    }
}
