package raylab.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.surface.BvhNodes;
import raylab.surface.Mesh;
import raylab.surface.Triangle;

/**
 * The packed engine's 4-wide traversal (PackedWide, PackedOctants): the collapsed tree holds every
 * leaf once, in boxes that hold its triangles, and visits the leaves in the binary tree's order for
 * every octant; the float constants of the slab distances bound the exact ones; rays at the edges
 * of its bounds agree with a loop over {@link Triangle} bit for bit. Seeds are in every message.
 */
class WideTraversalTest {

    /** Leaves of the 4-wide tree in the order its octant visits them (children by the order bytes). */
    static void wideOrder(float[] node, int ref, int octant, List<Integer> out) {
        if (ref < 0) {
            out.add(~ref);
            return;
        }
        int k = PackedWide.NODE * ref;
        int order = Float.floatToRawIntBits(node[k + 28 + (octant >> 2)]) >>> 8 * (octant & 3);
        int count = Float.floatToRawIntBits(node[k + 30]);
        for (int j = 0; j < count; j++) {
            int s = order >>> 2 * j & 3;
            wideOrder(node, Float.floatToRawIntBits(node[k + 24 + s]), octant, out);
        }
    }

    /** Leaves of the binary tree in its visit order for the octant (left first unless d < 0 on the axis). */
    static void binaryOrder(BvhNodes tree, int ref, int octant, List<Integer> out) {
        if (ref < 0) {
            out.add(~ref);
            return;
        }
        int k = BvhNodes.INNER * ref;
        int left = tree.inner[k + 12];
        int right = tree.inner[k + 13] >> 2;
        boolean rightFirst = (octant >> (tree.inner[k + 13] & 3) & 1) != 0;
        binaryOrder(tree, rightFirst ? right : left, octant, out);
        binaryOrder(tree, rightFirst ? left : right, octant, out);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9})
    void theWideTreeVisitsTheBinaryTreesLeavesInItsOrderForEveryOctant(long seed) {
        List<Triangle> tris = MeshEngineTest.randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        BvhNodes tree = engine.tree();
        PackedWide wide = engine.wide();
        int leaves = tree.leaf.length / 2;
        for (int octant = 0; octant < 8; octant++) {
            List<Integer> expected = new ArrayList<>();
            binaryOrder(tree, tree.rootRef, octant, expected);
            List<Integer> actual = new ArrayList<>();
            wideOrder(wide.node, wide.root, octant, actual);
            assertEquals(leaves, expected.size(), "seed " + seed + ": binary leaves");
            assertEquals(expected, actual, "seed " + seed + ", octant " + octant + ": leaf visit order");
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void everyChildBoxHoldsItsTrianglesAndEmptySlotsAreNeverEntered(long seed) {
        List<Triangle> tris = MeshEngineTest.scaled(MeshEngineTest.randomMesh(seed), seed % 2 == 0 ? -90 : 0,
                new Vec3(0, 0, 0));
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        BvhNodes tree = engine.tree();
        float[] node = engine.wide().node;
        int nodes = node.length / PackedWide.NODE;
        for (int w = 0; w < nodes; w++) {
            int k = PackedWide.NODE * w;
            int count = Float.floatToRawIntBits(node[k + 30]);
            assertTrue(count >= 2 && count <= 4, "seed " + seed + " node " + w + ": " + count + " children");
            for (int s = 0; s < 4; s++) {
                if (s >= count) {
                    for (int a = 0; a < 3; a++) {
                        assertEquals(Float.POSITIVE_INFINITY, node[k + 8 * a + s], "seed " + seed + ": empty min");
                        assertEquals(Float.NEGATIVE_INFINITY, node[k + 8 * a + 4 + s], "seed " + seed + ": empty max");
                    }
                    continue;
                }
                List<Integer> under = new ArrayList<>();
                wideOrder(node, Float.floatToRawIntBits(node[k + 24 + s]), 0, under);
                for (int l : under) {
                    for (int slot = tree.leaf[2 * l]; slot < tree.leaf[2 * l] + tree.leaf[2 * l + 1]; slot++) {
                        BoundingBox b = tris.get(tree.order[slot]).boundingBox();
                        double[] lo = {b.min.x, b.min.y, b.min.z};
                        double[] hi = {b.max.x, b.max.y, b.max.z};
                        for (int a = 0; a < 3; a++) {
                            String ctx = "seed " + seed + " node " + w + " child " + s + " triangle slot " + slot
                                    + " axis " + a;
                            assertTrue(node[k + 8 * a + s] <= lo[a], ctx + ": min " + node[k + 8 * a + s] + " > " + lo[a]);
                            assertTrue(node[k + 8 * a + 4 + s] >= hi[a], ctx + ": max " + node[k + 8 * a + 4 + s]
                                    + " < " + hi[a]);
                        }
                    }
                }
            }
        }
    }

    @Test
    void theRoundedOriginsLieStrictlyOnEitherSideOfTheOrigin() {
        // below(p) < p < above(p) exactly, for p over the traversal's range (|p| ≤ 2⁶⁰, down to 2⁻¹⁰⁷⁴),
        // and 0 and −0: a far plane's distance (o' − b)·m is then never 0 for a box the ray is in.
        long seed = 20261203;
        SplittableRandom r = new SplittableRandom(seed);
        for (int n = 0; n < 200_000; n++) {
            double p = switch (n % 5) {
                case 0 -> r.nextDouble(-10, 10);
                case 1 -> Math.scalb(r.nextDouble(-1, 1), r.nextInt(-200, 61));
                case 2 -> n % 10 == 2 ? 0.0 : n % 10 == 7 ? -0.0
                        : Math.scalb(1.0, r.nextInt(-1074, 61)) * (r.nextBoolean() ? 1 : -1);
                case 3 -> (double) (float) Math.scalb(r.nextDouble(-1, 1), r.nextInt(-150, 61)); // a float
                default -> Math.nextUp(Math.scalb((double) r.nextInt(-1000, 1000), r.nextInt(-30, 40)));
            };
            BigDecimal exact = new BigDecimal(p);
            float below = PackedWide.below(p);
            float above = PackedWide.above(p);
            String ctx = "seed " + seed + " #" + n + ": p " + p;
            assertTrue(new BigDecimal(below).compareTo(exact) < 0, ctx + ": below " + below + " not below p");
            assertTrue(new BigDecimal(above).compareTo(exact) > 0, ctx + ": above " + above + " not above p");
        }
        assertTrue(PackedWide.below(0x1p60) < 0x1p60 && PackedWide.above(-0x1p60) > -0x1p60, "at the bounds");
    }

    /**
     * Rays at the edges of the 4-wide traversal's bounds (direction components of 2⁻³⁰ and 2³⁰
     * and just beyond, origins at ±2⁶⁰ and beyond), rays in the planes of the tree's boxes and
     * along their faces, and shadow rays from points on the triangles; the tree against a loop
     * over Triangle, and the 4-wide traversal against the double one, bit for bit.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void raysAtTheEdgesOfTheFloatBoundsAgreeWithALinearLoop(long seed) {
        List<Triangle> tris = MeshEngineTest.randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        float[] node = engine.wide().node;
        SplittableRandom r = new SplittableRandom(seed * 31 + 7);
        BoundingBox box = mesh.boundingBox();
        Vec3 mid = box.min.plus(box.max).times(0.5);
        int hits = 0;
        int wide = 0;
        int[] ties = {0};
        for (int n = 0; n < 3000; n++) {
            Triangle t = tris.get(r.nextInt(tris.size()));
            Vec3 inside = t.a.plus(t.b.minus(t.a).times(r.nextDouble(0, 0.5))).plus(t.c.minus(t.a).times(r.nextDouble(0, 0.5)));
            Ray ray;
            switch (n % 6) {
                case 0 -> { // one component at the bound: 2⁻³⁰ or 2³⁰ in magnitude, or just beyond
                    Vec3 p = mid.plus(MeshEngineTest.rnd(r, -1, 1).times(8));
                    Vec3 d = inside.minus(p);
                    double s = Math.scalb(1.0, r.nextBoolean() ? -30 : 30) * (d.y < 0 ? -1 : 1);
                    double y = r.nextBoolean() ? s : r.nextBoolean() ? Math.nextDown(Math.abs(s)) * Math.signum(s)
                            : Math.nextUp(Math.abs(s)) * Math.signum(s);
                    double scale = Math.abs(y) / Math.max(Math.abs(d.y), 1e-300);
                    ray = new Ray(p, new Vec3(Math.scalb(d.x, Math.getExponent(scale)), y,
                            Math.scalb(d.z, Math.getExponent(scale))));
                }
                case 1 -> { // origin at ±2⁶⁰ or just beyond, toward the mesh
                    double far = r.nextBoolean() ? 0x1p60 : Math.nextUp(0x1p60);
                    Vec3 p = new Vec3(r.nextBoolean() ? far : -far, mid.y, mid.z);
                    ray = new Ray(p, inside.minus(p));
                }
                case 2 -> { // in the plane of a 4-wide box: origin on a box plane, toward a triangle
                    int w = r.nextInt(Math.max(1, node.length / PackedWide.NODE));
                    float plane = node.length == 0 ? (float) mid.x : node[PackedWide.NODE * w + r.nextInt(24)];
                    if (Float.isInfinite(plane)) {
                        plane = (float) mid.x;
                    }
                    Vec3 p = new Vec3(plane, inside.y + r.nextDouble(-1, 1), inside.z + r.nextDouble(-1, 1));
                    ray = new Ray(p, inside.minus(p));
                }
                case 3 -> { // along a box face: grazing at 2⁻³⁰ relative to the other components
                    Vec3 p = new Vec3(box.min.x, inside.y - 3, inside.z - 2);
                    ray = new Ray(p, new Vec3(0x1p-30, 3, 2));
                }
                case 4 -> { // a shadow ray from a point on a triangle toward a light
                    Vec3 light = mid.plus(MeshEngineTest.rnd(r, -1, 1).normalize().times(30));
                    ray = new Ray(inside, light.minus(inside), 1e-4, 1.0);
                }
                default -> { // from inside a child box of the root, in a random direction
                    Vec3 p = mid.plus(MeshEngineTest.rnd(r, -0.5, 0.5));
                    ray = new Ray(p, MeshEngineTest.rnd(r, -1, 1));
                }
            }
            if (engine.takesWide(ray)) {
                wide++;
            }
            hits += MeshEngineTest.agree(mesh, tris, ray, "seed " + seed + " #" + n + " " + ray, ties);
            for (boolean any : new boolean[] {false, true}) {
                raylab.ray.IntersectionRecord a = new raylab.ray.IntersectionRecord();
                raylab.ray.IntersectionRecord b = new raylab.ray.IntersectionRecord();
                boolean ha = engine.intersectWideWherePossible(a, ray, any);
                boolean hb = engine.intersectDouble(b, ray, any);
                String ctx = "seed " + seed + " #" + n + " " + ray + (any ? " any hit" : " closest");
                assertEquals(hb, ha, ctx + ": hit? double " + b + ", 4-wide " + a);
                if (hb && !any) {
                    assertEquals(Double.doubleToRawLongBits(b.t), Double.doubleToRawLongBits(a.t), ctx + ": t");
                    assertEquals(b.primitive, a.primitive, ctx + ": triangle");
                }
            }
        }
        System.out.printf("seed %d edge rays: %d hits, %d ties, %d of 3000 through the 4-wide traversal%n", seed, hits,
                ties[0], wide);
        assertTrue(hits > 500, "seed " + seed + ": too few hits to mean anything: " + hits);
        assertTrue(wide > 1500, "seed " + seed + ": too few rays through the 4-wide traversal: " + wide);
    }

    /**
     * Origins a double step, half a float step or a float step from the plane of a 4-wide box (or
     * on it), so that rounding the origin to float (PackedWide.below and above) decides whether the
     * ray is in the box; directions toward the mesh, along the plane (2⁻³⁰ across it) and away from
     * it; tMin 0, the smallest double or 10⁻⁴ (the plane rule's shortcut for tMin &gt; 0). The tree
     * against a loop over Triangle (closest and any hit), and the 4-wide traversal against the double
     * one, bit for bit.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {11, 12, 13, 14, 15, 16})
    void originsBetweenFloatsNextToBoxPlanesAgreeWithALinearLoop(long seed) {
        List<Triangle> tris = MeshEngineTest.randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        float[] node = engine.wide().node;
        SplittableRandom r = new SplittableRandom(seed * 131 + 5);
        BoundingBox box = mesh.boundingBox();
        Vec3 mid = box.min.plus(box.max).times(0.5);
        int hits = 0;
        int wide = 0;
        int[] ties = {0};
        double[] tMins = {0, Double.MIN_VALUE, 1e-4};
        for (int n = 0; n < 3000; n++) {
            Triangle t = tris.get(r.nextInt(tris.size()));
            Vec3 inside = t.a.plus(t.b.minus(t.a).times(r.nextDouble(0, 0.5))).plus(t.c.minus(t.a).times(r.nextDouble(0, 0.5)));
            int w = r.nextInt(Math.max(1, node.length / PackedWide.NODE));
            int slot = r.nextInt(24);
            float plane = node.length == 0 ? (float) mid.x : node[PackedWide.NODE * w + slot];
            if (Float.isInfinite(plane)) {
                plane = (float) t.a.x;
            }
            int axis = node.length == 0 ? 0 : slot / 8;
            double b = plane;
            double q = switch (n % 6) {
                case 0 -> b;
                case 1 -> Math.nextUp(b);
                case 2 -> Math.nextDown(b);
                case 3 -> b + Math.ulp(plane) / 2;
                case 4 -> b - Math.ulp(plane) / 2;
                default -> r.nextBoolean() ? Math.nextUp(plane) : Math.nextDown(plane);
            };
            double[] p = {inside.x + r.nextDouble(-1, 1), inside.y + r.nextDouble(-1, 1), inside.z + r.nextDouble(-1, 1)};
            p[axis] = q;
            Vec3 o = new Vec3(p[0], p[1], p[2]);
            Vec3 d = inside.minus(o);
            double[] dd = {d.x, d.y, d.z};
            switch (n / 6 % 3) {
                case 0 -> { // toward a point on a triangle
                }
                case 1 -> dd[axis] = Math.copySign(0x1p-30, r.nextBoolean() ? 1 : -1) * Math.max(1, Math.abs(dd[(axis + 1) % 3]));
                default -> {
                    for (int a = 0; a < 3; a++) {
                        dd[a] = -dd[a];
                    }
                }
            }
            double tMin = tMins[n % 3];
            Ray ray = new Ray(o, new Vec3(dd[0], dd[1], dd[2]), tMin, n % 4 == 0 ? 1.0 : Double.POSITIVE_INFINITY);
            if (engine.takesWide(ray)) {
                wide++;
            }
            String ctx = "seed " + seed + " #" + n + " (plane " + plane + " axis " + axis + ") " + ray;
            hits += MeshEngineTest.agree(mesh, tris, ray, ctx, ties);
            for (boolean any : new boolean[] {false, true}) {
                raylab.ray.IntersectionRecord a = new raylab.ray.IntersectionRecord();
                raylab.ray.IntersectionRecord c = new raylab.ray.IntersectionRecord();
                boolean ha = engine.intersectWideWherePossible(a, ray, any);
                boolean hc = engine.intersectDouble(c, ray, any);
                assertEquals(hc, ha, ctx + (any ? " any hit" : " closest") + ": hit? double " + c + ", 4-wide " + a);
                if (hc && !any) {
                    assertEquals(Double.doubleToRawLongBits(c.t), Double.doubleToRawLongBits(a.t), ctx + ": t");
                    assertEquals(c.primitive, a.primitive, ctx + ": triangle");
                    assertEquals(c.point, a.point, ctx + ": point");
                    assertEquals(c.normal, a.normal, ctx + ": normal");
                }
            }
        }
        System.out.printf("seed %d origins by box planes: %d hits, %d ties, %d of 3000 through the 4-wide traversal%n",
                seed, hits, ties[0], wide);
        assertTrue(hits > 300, "seed " + seed + ": too few hits to mean anything: " + hits);
        assertTrue(wide > 1500, "seed " + seed + ": too few rays through the 4-wide traversal: " + wide);
    }

    /**
     * Shadow rays that start on the mesh: at a vertex, on a shared edge (its midpoint, rounded), or on
     * a triangle, so that the triangles around the origin meet the ray at t = 0 or at a t of rounding
     * size that straddles tMin; tMin from the smallest double to 10⁻⁴, toward random lights, near and
     * far. Tree against loop, closest and any hit.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23, 24, 25, 26})
    void shadowRaysFromPointsOnTheMeshAgreeWithALinearLoop(long seed) {
        List<Triangle> tris = MeshEngineTest.randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        SplittableRandom r = new SplittableRandom(seed * 977 + 1);
        BoundingBox box = mesh.boundingBox();
        Vec3 mid = box.min.plus(box.max).times(0.5);
        double size = box.max.minus(box.min).length();
        double[] tMins = {Double.MIN_VALUE, 1e-300, 1e-12, 1e-4};
        int hits = 0;
        int[] ties = {0};
        for (int n = 0; n < 2500; n++) {
            Triangle t = tris.get(r.nextInt(tris.size()));
            Vec3 o = switch (n % 3) {
                case 0 -> r.nextBoolean() ? t.a : t.b;
                case 1 -> t.a.plus(t.b).times(0.5);
                default -> t.a.plus(t.b.minus(t.a).times(r.nextDouble(0, 0.5))).plus(t.c.minus(t.a).times(r.nextDouble(0, 0.5)));
            };
            Vec3 light = mid.plus(MeshEngineTest.rnd(r, -1, 1).normalize().times(size * (n % 2 == 0 ? 0.7 : 40)));
            Ray ray = new Ray(o, light.minus(o), tMins[n % 4], Math.nextDown(1.0));
            hits += MeshEngineTest.agree(mesh, tris, ray, "seed " + seed + " #" + n + " " + ray, ties);
        }
        System.out.printf("seed %d shadow rays from the mesh: %d blocked, %d ties%n", seed, hits, ties[0]);
        assertTrue(hits > 100, "seed " + seed + ": too few blocked rays to mean anything: " + hits);
    }

    @Test
    void stressRaysTakeTheWideTraversalWhereTheirBoundsHold() {
        // The stress rays of MeshEngineTest reach the 4-wide traversal, not only the double fallback.
        long seed = 3;
        List<Triangle> tris = MeshEngineTest.randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        int wide = 0;
        List<Ray> rays = MeshEngineTest.stressRays(seed, tris, 1400);
        for (Ray ray : rays) {
            wide += engine.takesWide(ray) ? 1 : 0;
        }
        assertTrue(wide > rays.size() / 2, "seed " + seed + ": " + wide + " of " + rays.size() + " through the 4-wide traversal");
    }
}
