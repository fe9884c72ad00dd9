package raylab.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The BVH must find exactly what the linear Group finds (same t, same surface) for every ray:
 * seeded random scenes of spheres, boxes and triangles, and awkward rays.
 */
class BvhTest {
    static final Material M = new FlatColor(Color.WHITE, "white");

    static Vec3 rndVec(SplittableRandom r, double lo, double hi) {
        return new Vec3(r.nextDouble(lo, hi), r.nextDouble(lo, hi), r.nextDouble(lo, hi));
    }

    /** n random primitives in [-10, 10]^3: spheres, boxes, triangles (some axis-aligned, flat boxes). */
    static List<Surface> randomScene(long seed, int n) {
        SplittableRandom r = new SplittableRandom(seed);
        List<Surface> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Vec3 c = rndVec(r, -10, 10);
            switch (r.nextInt(4)) {
                case 0 -> out.add(new Sphere(c, r.nextDouble(0.1, 1.5), M, "sphere#" + i));
                case 1 -> {
                    Vec3 h = rndVec(r, 0.05, 1.5);
                    out.add(new Box(c.minus(h), c.plus(h), M, "box#" + i));
                }
                case 2 -> out.add(new Triangle(c.plus(rndVec(r, -2, 2)), c.plus(rndVec(r, -2, 2)),
                        c.plus(rndVec(r, -2, 2)), M, "tri#" + i));
                default -> {
                    // a triangle in the plane z = c.z: its bounding box is flat
                    out.add(new Triangle(c, new Vec3(c.x + r.nextDouble(0.5, 3), c.y, c.z),
                            new Vec3(c.x, c.y + r.nextDouble(0.5, 3), c.z), M, "flat#" + i));
                }
            }
        }
        return out;
    }

    /** Random rays: from outside toward the scene, from inside, with zero direction components. */
    static List<Ray> randomRays(long seed, List<Surface> scene, int n) {
        SplittableRandom r = new SplittableRandom(seed * 31 + 7);
        List<Ray> rays = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Vec3 p;
            Vec3 d;
            switch (i % 4) {
                case 0 -> { // from far outside toward a point in the scene
                    p = rndVec(r, -1, 1).normalize().times(40);
                    d = rndVec(r, -9, 9).minus(p);
                }
                case 1 -> { // from inside the scene's bounds, any direction
                    p = rndVec(r, -10, 10);
                    d = rndVec(r, -1, 1);
                }
                case 2 -> { // zero components (+0.0 and -0.0), origin inside or outside
                    p = rndVec(r, -14, 14);
                    double[] c = {r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1)};
                    int zeros = 1 + r.nextInt(2);
                    for (int k = 0; k < zeros; k++) {
                        c[r.nextInt(3)] = r.nextBoolean() ? 0.0 : -0.0;
                    }
                    d = new Vec3(c[0], c[1], c[2]);
                    if (d.lengthSquared() == 0) {
                        d = new Vec3(0, 0, -1);
                    }
                }
                default -> { // origin on a box face plane or flat triangle plane, parallel to it
                    Surface s = scene.get(r.nextInt(scene.size()));
                    BoundingBox b = s.boundingBox();
                    int axis = r.nextInt(3);
                    double plane = r.nextBoolean() ? b.min.get(axis) : b.max.get(axis);
                    Vec3 q = rndVec(r, -14, 14);
                    p = new Vec3(axis == 0 ? plane : q.x, axis == 1 ? plane : q.y, axis == 2 ? plane : q.z);
                    Vec3 e = rndVec(r, -1, 1);
                    d = new Vec3(axis == 0 ? 0.0 : e.x, axis == 1 ? 0.0 : e.y, axis == 2 ? 0.0 : e.z);
                }
            }
            if (i % 7 == 3) { // a segment, like a shadow ray
                rays.add(new Ray(p, d, r.nextDouble(0, 0.5), r.nextDouble(0.5, 3)));
            } else {
                rays.add(new Ray(p, d));
            }
        }
        return rays;
    }

    static void assertSameHit(IntersectionRecord expected, boolean expectedHit, IntersectionRecord actual,
            boolean actualHit, String ctx) {
        assertEquals(expectedHit, actualHit, ctx + ": Group says hit=" + expectedHit + " (" + expected
                + "), BVH says hit=" + actualHit + " (" + actual + ")");
        assertEquals(expected.t, actual.t, ctx + ": closest t, Group hit " + expected.surface
                + ", BVH hit " + actual.surface);
        assertSame(expected.surface, actual.surface, ctx + ": surface at t=" + expected.t);
        assertEquals(expected.point, actual.point, ctx + ": point");
        assertEquals(expected.normal, actual.normal, ctx + ": normal");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10})
    void closestHitAgreesWithGroup(long seed) {
        List<Surface> scene = randomScene(seed, 60 + (int) (seed * 37 % 300));
        Group group = new Group(scene, "group");
        Bvh bvh = new Bvh(scene, "bvh");
        assertEquals(scene.size(), bvh.primitiveCount(), "seed " + seed + ": primitive count");
        assertEquals(group.boundingBox().min, bvh.boundingBox().min, "seed " + seed + ": box min");
        assertEquals(group.boundingBox().max, bvh.boundingBox().max, "seed " + seed + ": box max");
        int hits = 0;
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (Ray ray : randomRays(seed, scene, 3000)) {
            g.reset();
            b.reset();
            boolean gh = group.intersect(g, ray);
            boolean bh = bvh.intersect(b, ray);
            assertSameHit(g, gh, b, bh, "seed " + seed + ", ray " + ray);
            hits += gh ? 1 : 0;
        }
        assertTrue(hits > 300, "seed " + seed + ": only " + hits + " of 3000 rays hit; the test would be weak");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void aPreviousCloserHitInTheRecordIsRespected(long seed) {
        List<Surface> scene = randomScene(seed, 200);
        Group group = new Group(scene, "group");
        Bvh bvh = new Bvh(scene, "bvh");
        Surface other = new Sphere(Vec3.ZERO, 1, M, "earlier");
        SplittableRandom r = new SplittableRandom(seed);
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (Ray ray : randomRays(seed, scene, 1500)) {
            double t0 = r.nextDouble(0, 30);
            g.reset();
            g.set(t0, Vec3.ZERO, new Vec3(0, 0, 1), other);
            b.copyFrom(g);
            boolean gh = group.intersect(g, ray);
            boolean bh = bvh.intersect(b, ray);
            assertSameHit(g, gh, b, bh, "seed " + seed + ", record t=" + t0 + ", ray " + ray);
            if (!bh) {
                assertSame(other, b.surface, "seed " + seed + ": record must be untouched on a miss, ray " + ray);
                assertEquals(t0, b.t, "seed " + seed + ": t untouched on a miss");
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33, 34})
    void anyHitAgreesWithClosestHit(long seed) {
        List<Surface> scene = randomScene(seed, 250);
        Group group = new Group(scene, "group");
        Bvh bvh = new Bvh(scene, "bvh");
        IntersectionRecord scratch = new IntersectionRecord();
        IntersectionRecord rec = new IntersectionRecord();
        SplittableRandom r = new SplittableRandom(seed);
        int blocked = 0;
        for (Ray ray : randomRays(seed, scene, 3000)) {
            // shadow-ray-like segments of various lengths
            Ray seg = new Ray(ray.p, ray.d, 0, r.nextDouble(0.1, 20));
            rec.reset();
            boolean expected = group.intersect(rec, seg);
            assertEquals(expected, group.intersectsAny(seg, scratch), "seed " + seed + ": Group any-hit, " + seg);
            assertEquals(expected, bvh.intersectsAny(seg, scratch),
                    "seed " + seed + ": BVH any-hit disagrees with the closest hit " + rec + " for " + seg);
            blocked += expected ? 1 : 0;
        }
        assertTrue(blocked > 200 && blocked < 2800, "seed " + seed + ": " + blocked + " of 3000 blocked; weak test");
    }

    @Test
    void emptyBvh() {
        Bvh bvh = new Bvh(List.of(), "empty");
        IntersectionRecord rec = new IntersectionRecord();
        Ray ray = new Ray(Vec3.ZERO, new Vec3(0, 0, -1));
        assertFalse(bvh.intersect(rec, ray), "empty BVH never hits");
        assertFalse(rec.hasHit(), "record untouched");
        assertFalse(bvh.intersectsAny(ray, rec), "empty BVH blocks nothing");
        assertTrue(bvh.boundingBox().isEmpty(), "empty box");
        assertEquals(0, bvh.primitiveCount(), "no primitives");
    }

    @Test
    void onePrimitive() {
        Sphere s = new Sphere(new Vec3(0, 0, -5), 1, M, "only");
        Bvh bvh = new Bvh(List.of(s), "one");
        IntersectionRecord rec = new IntersectionRecord();
        Ray ray = new Ray(Vec3.ZERO, new Vec3(0, 0, -1));
        assertTrue(bvh.intersect(rec, ray), "hits the sphere");
        assertEquals(4.0, rec.t, 1e-12, "t of the front of the sphere");
        assertSame(s, rec.surface, "surface");
        assertEquals(1, rec.tests, "one intersection test");
        rec.reset();
        assertFalse(bvh.intersect(rec, new Ray(Vec3.ZERO, new Vec3(0, 1, 0))), "misses upward");
        assertEquals(1, bvh.nodeCount(), "a single leaf");
        assertEquals(s.boundingBox().min, bvh.boundingBox().min, "box min");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {41, 42})
    void allPrimitivesWithTheSameCentroid(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        Vec3 c = new Vec3(1, 2, 3);
        List<Surface> scene = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            if (i % 2 == 0) {
                scene.add(new Sphere(c, r.nextDouble(0.1, 5), M, "sphere#" + i));
            } else {
                Vec3 h = rndVec(r, 0.1, 4);
                scene.add(new Box(c.minus(h), c.plus(h), M, "box#" + i));
            }
        }
        Group group = new Group(scene, "group");
        Bvh bvh = new Bvh(scene, "bvh");
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (Ray ray : randomRays(seed, scene, 1000)) {
            g.reset();
            b.reset();
            assertSameHit(g, group.intersect(g, ray), b, bvh.intersect(b, ray), "seed " + seed + ", " + ray);
        }
    }

    /** Centroids spaced geometrically: binning peels off a few primitives per level, a deep tree. */
    @Test
    void deepUnbalancedTree() {
        List<Surface> scene = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            double x = Math.scalb(1.0, i);
            scene.add(new Sphere(new Vec3(x, 0, 0), 0.25 * x, M, "sphere#" + i));
        }
        Group group = new Group(scene, "group");
        Bvh bvh = new Bvh(scene, "bvh");
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (int i = 0; i < 400; i += 3) {
            double x = Math.scalb(1.0, i);
            for (Ray ray : List.of(new Ray(new Vec3(x, 0, 10 * x), new Vec3(0, 0, -1)),
                    new Ray(new Vec3(0.5, 0, 0), new Vec3(1, 0, 0)),
                    new Ray(new Vec3(x * 1.1, x, 0), new Vec3(-0.1, -1, 0.001)))) {
                g.reset();
                b.reset();
                assertSameHit(g, group.intersect(g, ray), b, bvh.intersect(b, ray), "ray " + ray);
                assertEquals(group.intersectsAny(ray, g), bvh.intersectsAny(ray, b), "any-hit, ray " + ray);
            }
        }
    }

    @Test
    void deterministicBuild() {
        List<Surface> scene = randomScene(99, 500);
        Bvh a = new Bvh(scene, "a");
        Bvh b = new Bvh(new ArrayList<>(scene), "b");
        assertEquals(a.nodeCount(), b.nodeCount(), "same number of nodes");
        IntersectionRecord ra = new IntersectionRecord();
        IntersectionRecord rb = new IntersectionRecord();
        for (Ray ray : randomRays(99, scene, 2000)) {
            ra.reset();
            rb.reset();
            ra.tests = 0;
            rb.tests = 0;
            assertSameHit(ra, a.intersect(ra, ray), rb, b.intersect(rb, ray), "ray " + ray);
            assertEquals(ra.tests, rb.tests, "same tree, same traversal: test count for " + ray);
        }
    }

    @ParameterizedTest(name = "shuffle seed {0}")
    @ValueSource(longs = {51, 52, 53})
    void inputOrderDoesNotChangeTheClosestHit(long seed) {
        List<Surface> scene = randomScene(seed, 300);
        List<Surface> shuffled = new ArrayList<>(scene);
        Collections.shuffle(shuffled, new Random(seed));
        Bvh a = new Bvh(scene, "a");
        Bvh b = new Bvh(shuffled, "b");
        IntersectionRecord ra = new IntersectionRecord();
        IntersectionRecord rb = new IntersectionRecord();
        for (Ray ray : randomRays(seed, scene, 1500)) {
            ra.reset();
            rb.reset();
            assertSameHit(ra, a.intersect(ra, ray), rb, b.intersect(rb, ray), "seed " + seed + ", ray " + ray);
        }
    }

    @Test
    void bvhTestsFarFewerPrimitivesThanGroup() {
        List<Surface> scene = new ArrayList<>();
        SplittableRandom r = new SplittableRandom(5);
        for (int i = 0; i < 2000; i++) {
            scene.add(new Sphere(rndVec(r, -50, 50), 0.5, M, "s" + i));
        }
        Bvh bvh = new Bvh(scene, "bvh");
        IntersectionRecord rec = new IntersectionRecord();
        long tests = 0;
        int rays = 500;
        for (int i = 0; i < rays; i++) {
            Vec3 p = rndVec(r, -1, 1).normalize().times(200);
            rec.reset();
            rec.tests = 0;
            bvh.intersect(rec, new Ray(p, rndVec(r, -50, 50).minus(p)));
            tests += rec.tests;
        }
        double perRay = (double) tests / rays;
        assertTrue(perRay < 200, "BVH over 2000 spheres should test far fewer than 2000 per ray, got " + perRay);
        assertTrue(perRay >= 1, "BVH counts its tests, got " + perRay);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {61, 62})
    void meshDelegatesToItsHierarchy(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        Material mm = new FlatColor(new Color(1, 0, 0), "red");
        List<Triangle> tris = new ArrayList<>();
        for (int i = 0; i < 150; i++) {
            Vec3 c = rndVec(r, -8, 8);
            tris.add(new Triangle(c, c.plus(rndVec(r, -2, 2)), c.plus(rndVec(r, -2, 2)), mm, "t" + i));
        }
        Mesh mesh = new Mesh(tris, "mesh");
        Group group = new Group(tris, "group");
        assertEquals(150, mesh.primitiveCount(), "primitive count");
        assertSame(mm, mesh.material(), "mesh material is its triangles' material");
        assertEquals(tris, mesh.triangles(), "triangles in file order");
        assertEquals(group.boundingBox().min, mesh.boundingBox().min, "box min");
        assertEquals(group.boundingBox().max, mesh.boundingBox().max, "box max");
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        List<Surface> asSurfaces = new ArrayList<>(tris);
        int hits = 0;
        for (Ray ray : randomRays(seed, asSurfaces, 1500)) {
            g.reset();
            b.reset();
            boolean gh = group.intersect(g, ray);
            boolean bh = mesh.intersect(b, ray);
            String ctx = "seed " + seed + ", ray " + ray;
            // The packed mesh reports itself as the surface and the triangle's file index.
            assertEquals(gh, bh, ctx + ": hit");
            assertEquals(g.t, b.t, ctx + ": t");
            assertEquals(g.point, b.point, ctx + ": point");
            assertEquals(g.normal, b.normal, ctx + ": normal");
            if (gh) {
                assertSame(mesh, b.surface, ctx + ": surface");
                assertEquals(tris.indexOf(g.surface), b.primitive, ctx + ": triangle index");
            }
            if (gh) {
                hits++;
                assertSame(mm, b.material, "the hit carries the mesh material");
            }
            Ray seg = new Ray(ray.p, ray.d, 0, 1);
            g.reset();
            assertEquals(group.intersect(g, seg), mesh.intersectsAny(seg, b), "any-hit, seed " + seed + ", " + seg);
        }
        assertTrue(hits > 100, "seed " + seed + ": too few hits (" + hits + ")");
    }

    /** Delegates to a primitive and counts the tests of the current ray; stops a runaway traversal. */
    static final class Counted extends Surface {
        final Surface inner;
        final int[] calls;
        final int limit;

        Counted(Surface inner, int[] calls, int limit) {
            super(inner.material(), inner.name());
            this.inner = inner;
            this.calls = calls;
            this.limit = limit;
        }

        @Override
        public boolean intersect(IntersectionRecord rec, Ray ray) {
            if (++calls[0] > limit) {
                throw new AssertionError("more than " + limit + " primitive tests for one ray: the traversal"
                        + " revisits nodes (a broken child link?), ray " + ray);
            }
            return inner.intersect(rec, ray);
        }

        @Override
        public BoundingBox boundingBox() {
            return inner.boundingBox();
        }
    }

    /** Each primitive sits in one leaf, so one ray tests it at most once: also on trees of many nodes. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {71, 72})
    void everyPrimitiveIsTestedAtMostOncePerRay(long seed) {
        int n = 1500; // far more nodes than the initial node capacity
        int[] calls = new int[1];
        List<Surface> scene = new ArrayList<>();
        for (Surface s : randomScene(seed, n)) {
            scene.add(new Counted(s, calls, n));
        }
        Bvh bvh = new Bvh(scene, "bvh");
        assertTrue(bvh.nodeCount() > 64, "seed " + seed + ": the tree has " + bvh.nodeCount() + " nodes");
        IntersectionRecord rec = new IntersectionRecord();
        for (Ray ray : randomRays(seed, scene, 1000)) {
            calls[0] = 0;
            rec.reset();
            bvh.intersect(rec, ray);
            calls[0] = 0;
            bvh.intersectsAny(ray, rec);
        }
    }
}
