package raylab.scene.types;

import java.util.List;

import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.scene.SceneException;
import raylab.scene.SurfaceType;
import raylab.surface.Mesh;
import raylab.surface.Surface;

/**
 * The built-in triangle mesh: {@code {"type": "mesh", "file": "bunny.obj", "scale": s,
 * "translate": [x, y, z]}}, each vertex v of the OBJ file (relative to the scene's directory)
 * placed at v·s + translate. A variant moves its translate; data cases have no meshes.
 */
public final class MeshType implements SurfaceType {
    @Override
    public String type() {
        return "mesh";
    }

    @Override
    public String description() {
        return "a mesh";
    }

    @Override
    public List<String> keys() {
        return List.of("type", "name", "file", "material", "scale", "translate");
    }

    @Override
    public List<String> requiredKeys() {
        return List.of("type", "file", "material");
    }

    /** Its entry under {@code $defs} of scenes/scene.schema.json: each key described and typed. */
    @Override
    public ObjectNode schema() {
        return SchemaJson.entry(this, "A triangle mesh read from a Wavefront OBJ file; each vertex v becomes"
                + " v·scale + translate.", "A triangle mesh from an OBJ file.", """
                {
                  "file": {"description": "Path of the OBJ file, relative to the scene file's directory.", "type": "string",
                           "minLength": 1},
                  "scale": {"description": "Uniform scale factor (positive). Default: 1.", "type": "number",
                            "exclusiveMinimum": 0, "default": 1},
                  "translate": {"description": "Offset added after scaling. Default: [0, 0, 0].", %s}
                }
                """.formatted(SchemaJson.POINT));
    }

    @Override
    public Surface build(Fields f, Material m, String name) throws SceneException {
        String rel = f.string("file");
        if (rel.isBlank()) {
            throw f.fail("file", "file must not be empty: give the path of an OBJ file");
        }
        double scale = f.has("scale") ? f.positive("scale") : 1;
        Vec3 translate = f.has("translate") ? f.vec3("translate") : Vec3.ZERO;
        ObjFile obj = f.objFile("file");
        double[] v = obj.triangleVertices();
        // Each coordinate as Vec3.times(scale).plus(translate) would compute it.
        double tx = translate.x;
        double ty = translate.y;
        double tz = translate.z;
        for (int i = 0; i < v.length; i += 3) {
            v[i] = v[i] * scale + tx;
            v[i + 1] = v[i + 1] * scale + ty;
            v[i + 2] = v[i + 2] * scale + tz;
            if (!Double.isFinite(v[i]) || !Double.isFinite(v[i + 1]) || !Double.isFinite(v[i + 2])) {
                throw f.fail(f.has("scale") ? "scale" : "file", "scaling and translating " + obj.path()
                        + " gives coordinates too large to represent");
            }
        }
        return new Mesh(v, m, name);
    }

    @Override
    public void move(ObjectNode s, double[] d) {
        Moves.point(s, "translate", d);
    }

    /** Its triangles. */
    @Override
    public List<Surface> primitives(Surface s) {
        return s instanceof Mesh mesh ? List.copyOf(mesh.triangles()) : null;
    }

    @Override
    public boolean inDataCases() {
        return false;
    }
}
