package raylab.scene.types;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;

import raylab.material.NormalColor;
import raylab.math.Vec3;
import raylab.scene.SurfaceType;
import raylab.scene.SurfaceTypes;
import raylab.surface.Box;
import raylab.surface.Mesh;
import raylab.surface.Sphere;
import raylab.surface.Surface;

/**
 * The built-in surface types answer through {@link SurfaceType} what the framework used to ask
 * of each class directly: the render plan's outside rule, a mesh's primitives, trace's sphere
 * rule, a variant's move, the data cases' format. (The loader's messages are held by
 * MalformedSceneTest and SceneLoaderTest, the moves by SceneVariantsTest.)
 */
class BuiltInTypesTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final NormalColor M = new NormalColor("n");

    @Test
    void builtInTypesComeFirstInDocumentationOrder() {
        assertEquals(List.of("sphere", "box", "triangle", "mesh"),
                List.copyOf(SurfaceTypes.all().keySet()).subList(0, 4), "SurfaceTypes.all() starts with");
        assertEquals(SurfaceTypes.builtIn().keySet(), java.util.Set.of("sphere", "box", "triangle", "mesh"));
    }

    @Test
    void sphereSaysWhetherTheEyeIsOutsideAndOnlyForSpheres() {
        SurfaceType t = SurfaceTypes.all().get("sphere");
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "s");
        assertEquals(Boolean.TRUE, t.eyeOutsideConvex(s, new Vec3(0, 0, 1.01), 1e-6), "eye at 1.01 from a unit sphere");
        assertEquals(Boolean.FALSE, t.eyeOutsideConvex(s, new Vec3(0, 0, 0.5), 1e-6), "eye at 0.5 inside a unit sphere");
        assertEquals(Boolean.FALSE, t.eyeOutsideConvex(s, new Vec3(0, 0, 1), 1e-6), "eye on the sphere");
        assertNull(t.eyeOutsideConvex(new Box(Vec3.ZERO, new Vec3(1, 1, 1), M, "b"), Vec3.ZERO, 1e-6), "a box is not the sphere's");
    }

    @Test
    void boxSaysWhetherTheEyeIsOutsideASlab() {
        SurfaceType t = SurfaceTypes.all().get("box");
        Box b = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), M, "b");
        assertEquals(Boolean.TRUE, t.eyeOutsideConvex(b, new Vec3(0, 1.5, 0), 1e-6), "eye above the box");
        assertEquals(Boolean.FALSE, t.eyeOutsideConvex(b, new Vec3(0.9, -0.9, 0), 1e-6), "eye inside the box");
        assertNull(t.eyeOutsideConvex(new Sphere(Vec3.ZERO, 1, M, "s"), Vec3.ZERO, 1e-6), "a sphere is not the box's");
    }

    @Test
    void sphereTraceRuleIsTheOutwardNormal() {
        SurfaceType t = SurfaceTypes.all().get("sphere");
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "s");
        assertEquals("a sphere's normal points out of the sphere, (x - c)/R; this one points into it",
                t.traceRule(s, new Vec3(0, 0, 1), new Vec3(0, 0, -1)));
        assertNull(t.traceRule(s, new Vec3(0, 0, 1), new Vec3(0, 0, 1)), "an outward normal breaks no rule");
        assertNull(SurfaceTypes.all().get("box").traceRule(s, new Vec3(0, 0, 1), new Vec3(0, 0, -1)),
                "only the sphere's type says it");
    }

    @Test
    void meshIsMadeOfItsTriangles() {
        Mesh mesh = new Mesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, M, "m");
        List<Surface> parts = SurfaceTypes.all().get("mesh").primitives(mesh);
        assertEquals(2, parts.size(), "primitives of a two-triangle mesh");
        assertEquals(mesh.triangles(), parts);
        assertNull(SurfaceTypes.all().get("sphere").primitives(mesh), "only the mesh's type splits it");
    }

    @Test
    void triangleMovesEachVertexRounded() throws Exception {
        ObjectNode s = (ObjectNode) JSON.readTree(
                "{\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 0.1, 0]]}");
        SurfaceTypes.all().get("triangle").move(s, new double[] {0.2, 0, -1});
        assertEquals("[[0.2,0.0,-1.0],[1.2,0.0,-1.0],[0.2,0.1,-1.0]]", s.get("vertices").toString());
    }

    @Test
    void meshWithoutTranslateGetsOne() throws Exception {
        ObjectNode s = (ObjectNode) JSON.readTree("{\"type\": \"mesh\", \"file\": \"a.obj\"}");
        SurfaceTypes.all().get("mesh").move(s, new double[] {1, 2, 3});
        assertEquals("[1.0,2.0,3.0]", s.get("translate").toString());
    }

    @Test
    void dataCasesKeepTheirFormats() throws Exception {
        assertEquals("sphere \"radius\" must be a number > 0", SurfaceTypes.all().get("sphere")
                .caseProblem(JSON.readTree("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 0}")));
        assertEquals("\"c\" must be an array of 3 numbers", SurfaceTypes.all().get("triangle")
                .caseProblem(JSON.readTree("{\"type\": \"triangle\", \"a\": [0, 0, 0], \"b\": [1, 0, 0]}")));
        assertNull(SurfaceTypes.all().get("box")
                .caseProblem(JSON.readTree("{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [1, 1, 1]}")));
        assertEquals(false, SurfaceTypes.all().get("mesh").inDataCases(), "a mesh in a data case");
    }
}
