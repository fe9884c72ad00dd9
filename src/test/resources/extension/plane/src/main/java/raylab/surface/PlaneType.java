package raylab.surface;

import java.util.List;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.scene.SceneException;
import raylab.scene.SurfaceType;

/** The scene entry of {@link Plane}: {"type": "plane", "point": [x, y, z], "normal": [x, y, z]}. */
public final class PlaneType implements SurfaceType {
    @Override
    public String type() {
        return "plane";
    }

    @Override
    public String description() {
        return "a plane";
    }

    @Override
    public List<String> keys() {
        return List.of("type", "name", "point", "normal", "material");
    }

    @Override
    public List<String> requiredKeys() {
        return List.of("type", "point", "normal", "material");
    }

    @Override
    public Surface build(Fields f, Material material, String name) throws SceneException {
        Vec3 n = f.vec3("normal");
        if (!(n.length() > 0)) {
            throw f.fail("normal", "a plane's normal must not be [0, 0, 0]");
        }
        return new Plane(f.vec3("point"), n, material, name);
    }

    @Override
    public String traceNote(Surface s, Ray ray) {
        if (s instanceof Plane p && p.normal.dot(ray.d) == 0) {
            return "; the ray is parallel to the plane (n·d = 0)";
        }
        return "";
    }

    @Override
    public void move(ObjectNode surface, double[] d) {
        ArrayNode p = (ArrayNode) surface.get("point");
        ArrayNode moved = surface.arrayNode();
        for (int i = 0; i < 3; i++) {
            moved.add(p.get(i).asDouble() + d[i]);
        }
        surface.set("point", moved);
    }
}
