package raylab.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Mesh;
import raylab.surface.Triangle;

/**
 * The Vector API traversal ({@code PackedVector}) against the scalar one ({@link PackedOctants})
 * and a loop over {@link Triangle}: the same hit, t to the bit, triangle, point, normal and count of
 * triangle tests on every ray (it enters the same boxes in the same order), closest and any hit.
 *
 * <p>It needs the JVM started with {@code --add-modules jdk.incubator.vector}: Maven's surefire
 * does so and sets {@code raylab.test.vector=required}, under which a missing module fails the
 * tests instead of skipping them (pom.xml).
 */
class VectorTraversalTest {
    private static VectorTraversal vector() {
        Object v = VectorTraversal.load();
        if ("required".equals(System.getProperty("raylab.test.vector"))) {
            assertInstanceOf(VectorTraversal.class, v, "the Vector API traversal cannot be had: " + v);
        }
        assumeTrue(v instanceof VectorTraversal, () -> "skipped: " + v);
        return (VectorTraversal) v;
    }

    @Test
    void loadSaysWhyWhenThereIsNoVectorTraversal() {
        Object v = VectorTraversal.load();
        if (VectorTraversal.moduleResolved()) {
            assertEquals("raylab.mesh.PackedVector", v.getClass().getName(), "with the module: " + v);
        } else {
            assertEquals("the JVM was started without --add-modules jdk.incubator.vector", v);
        }
        // Without -Draylab.mesh.traversal=vector the engine keeps the scalar traversal.
        assertNull(System.getProperty("raylab.mesh.traversal"));
        assertNull(VectorTraversal.fromProperty());
        assertNull(PackedTriangles.VECTOR);
    }

    /**
     * MeshEngineTest's stress rays (grazing, along shared edges, from far away, from inside the box,
     * huge and tiny direction components) and random rays, on the mesh as built, scaled by 2⁻⁹⁰ and
     * 2⁵⁰ and moved by 10⁶; shadow rays from points on the mesh.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void theVectorTraversalFindsWhatTheScalarOneFinds(long seed) {
        VectorTraversal vector = vector();
        int[] scales = {0, -90, 50, 0};
        Vec3[] moves = {new Vec3(0, 0, 0), new Vec3(0, 0, 0), new Vec3(0, 0, 0), new Vec3(3e6, -1e6, 2.5e6)};
        int wide = 0;
        int hits = 0;
        int rays = 0;
        for (int v = 0; v < scales.length; v++) {
            List<Triangle> tris = MeshEngineTest.scaled(MeshEngineTest.randomMesh(seed), scales[v], moves[v]);
            Mesh mesh = new Mesh(tris, "mesh");
            PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
            List<Ray> all = new ArrayList<>(MeshEngineTest.stressRays(seed + 100 * v, tris, 1000));
            all.addAll(MeshEngineTest.randomRays(seed + 100 * v, tris, 500));
            all.addAll(shadowRaysFromTheMesh(seed + 100 * v, tris, 500));
            for (Ray ray : all) {
                wide += engine.takesWide(ray) ? 1 : 0;
                hits += compare(engine, vector, tris, ray, "seed " + seed + " variant " + v + " " + ray);
                rays++;
            }
        }
        System.out.printf("seed %d: %d rays, %d through the 4-wide traversal, %d hit%n", seed, rays, wide, hits);
        // The tiny variant (2⁻⁹⁰) is outside the float bounds: its rays take the double traversal.
        assertTrue(wide > 3 * rays / 10, "seed " + seed + ": too few rays through the 4-wide traversal: " + wide + " of " + rays);
        assertTrue(hits > rays / 10, "seed " + seed + ": too few hits to mean anything: " + hits + " of " + rays);
    }

    /** Shadow rays from vertices, edge midpoints and points of triangles toward lights near and far. */
    static List<Ray> shadowRaysFromTheMesh(long seed, List<Triangle> tris, int n) {
        SplittableRandom r = new SplittableRandom(seed * 977 + 3);
        BoundingBox box = new Mesh(tris, "box").boundingBox();
        Vec3 mid = box.min.plus(box.max).times(0.5);
        double size = box.max.minus(box.min).length();
        double[] tMins = {Double.MIN_VALUE, 1e-12, 1e-4};
        List<Ray> rays = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Triangle t = tris.get(r.nextInt(tris.size()));
            Vec3 o = switch (i % 3) {
                case 0 -> t.a;
                case 1 -> t.a.plus(t.b).times(0.5);
                default -> t.a.plus(t.b.minus(t.a).times(r.nextDouble(0, 0.5))).plus(t.c.minus(t.a).times(r.nextDouble(0, 0.5)));
            };
            Vec3 light = mid.plus(MeshEngineTest.rnd(r, -1, 1).normalize().times(size * (i % 2 == 0 ? 0.7 : 40)));
            rays.add(new Ray(o, light.minus(o), tMins[i % 3], Math.nextDown(1.0)));
        }
        return rays;
    }

    /** Vector against scalar, bit for bit, and against the loop over Triangle; 1 when the ray hits. */
    private static int compare(PackedTriangles engine, VectorTraversal vector, List<Triangle> tris, Ray ray, String ctx) {
        int hit = 0;
        for (boolean any : new boolean[] {false, true}) {
            IntersectionRecord s = new IntersectionRecord();
            IntersectionRecord v = new IntersectionRecord();
            boolean hs = engine.intersectWideWith(null, s, ray, any);
            boolean hv = engine.intersectWideWith(vector, v, ray, any);
            String c = ctx + (any ? " any hit" : " closest");
            assertEquals(hs, hv, c + ": hit? scalar " + s + ", vector " + v);
            assertEquals(s.tests, v.tests, c + ": triangle tests (the same boxes entered in the same order)");
            if (hs) {
                assertEquals(Double.doubleToRawLongBits(s.t), Double.doubleToRawLongBits(v.t), c + ": t " + s.t + " vs " + v.t);
                assertEquals(s.primitive, v.primitive, c + ": triangle");
                assertEquals(s.point, v.point, c + ": point");
                assertEquals(s.normal, v.normal, c + ": normal");
            }
            if (!any) {
                IntersectionRecord loop = new IntersectionRecord();
                int want = MeshEngineTest.linear(tris, loop, ray);
                assertEquals(want >= 0, hv, c + ": hit? loop over Triangle " + loop + ", vector " + v);
                if (hv) {
                    assertEquals(Double.doubleToRawLongBits(loop.t), Double.doubleToRawLongBits(v.t),
                            c + ": t, loop " + loop.t + " vs vector " + v.t);
                    hit = 1;
                }
            }
        }
        return hit;
    }
}
