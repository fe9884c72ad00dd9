package raylab.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
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
import raylab.surface.Bvh;
import raylab.surface.Group;
import raylab.surface.Mesh;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * The packed mesh engine against an independent oracle: a plain loop over the same triangles as
 * {@link Triangle} objects. Same hit or miss, the same t to the last bit, the same point and
 * normal, and the same triangle; the one allowed difference (the tie rule, docs/mesh-engine.md) is
 * a second triangle hit at exactly the same t, since both the loop and the tree keep the first
 * one they find and they find them in different orders. Seeded meshes: random soups (overlaps,
 * slivers, degenerate triangles) and closed grids with shared edges and vertices, which rays
 * cross exactly on edges.
 */
class MeshEngineTest {
    static final Material M = new FlatColor(Color.WHITE, "white");

    static Vec3 rnd(SplittableRandom r, double lo, double hi) {
        return new Vec3(r.nextDouble(lo, hi), r.nextDouble(lo, hi), r.nextDouble(lo, hi));
    }

    /** A random soup, a displaced grid with shared edges, or a cube of grid faces. */
    static List<Triangle> randomMesh(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        List<Triangle> out = new ArrayList<>();
        switch ((int) (seed % 3)) {
            case 0 -> {
                int n = 50 + r.nextInt(400);
                for (int i = 0; i < n; i++) {
                    Vec3 c = rnd(r, -5, 5);
                    Vec3 a = c.plus(rnd(r, -1.5, 1.5));
                    Vec3 b = c.plus(rnd(r, -1.5, 1.5));
                    Vec3 d = switch (r.nextInt(10)) {
                        case 0 -> a; // degenerate: a repeated vertex
                        case 1 -> a.plus(b.minus(a).times(0.5)); // degenerate: collinear
                        default -> c.plus(rnd(r, -1.5, 1.5));
                    };
                    out.add(new Triangle(a, b, d, M, "t" + i));
                }
            }
            case 1 -> {
                int k = 5 + r.nextInt(25);
                Vec3[][] v = new Vec3[k + 1][k + 1];
                for (int i = 0; i <= k; i++) {
                    for (int j = 0; j <= k; j++) {
                        v[i][j] = new Vec3(-4 + 8.0 * i / k, r.nextDouble(-0.3, 0.3), -4 + 8.0 * j / k);
                    }
                }
                for (int i = 0; i < k; i++) {
                    for (int j = 0; j < k; j++) {
                        out.add(new Triangle(v[i][j], v[i + 1][j], v[i + 1][j + 1], M, "g" + out.size()));
                        out.add(new Triangle(v[i][j], v[i + 1][j + 1], v[i][j + 1], M, "g" + out.size()));
                    }
                }
            }
            default -> {
                int k = 2 + r.nextInt(8);
                for (int axis = 0; axis < 3; axis++) {
                    for (double side : new double[] {-2, 2}) {
                        for (int i = 0; i < k; i++) {
                            for (int j = 0; j < k; j++) {
                                Vec3 p00 = face(axis, side, i, j, k);
                                Vec3 p10 = face(axis, side, i + 1, j, k);
                                Vec3 p11 = face(axis, side, i + 1, j + 1, k);
                                Vec3 p01 = face(axis, side, i, j + 1, k);
                                out.add(new Triangle(p00, p10, p11, M, "c" + out.size()));
                                out.add(new Triangle(p00, p11, p01, M, "c" + out.size()));
                            }
                        }
                    }
                }
            }
        }
        return out;
    }

    private static Vec3 face(int axis, double side, int i, int j, int k) {
        double u = -2 + 4.0 * i / k;
        double w = -2 + 4.0 * j / k;
        return axis == 0 ? new Vec3(side, u, w) : axis == 1 ? new Vec3(u, side, w) : new Vec3(u, w, side);
    }

    /** Rays from outside, from inside, through vertices, with zero direction components, segments. */
    static List<Ray> randomRays(long seed, List<Triangle> mesh, int n) {
        SplittableRandom r = new SplittableRandom(seed * 7919 + 1);
        List<Ray> rays = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Vec3 p;
            Vec3 d;
            switch (i % 5) {
                case 0 -> {
                    p = rnd(r, -1, 1).normalize().times(20);
                    d = rnd(r, -4, 4).minus(p);
                }
                case 1 -> {
                    p = rnd(r, -3, 3);
                    d = rnd(r, -1, 1);
                }
                case 2 -> { // aimed exactly at a vertex: on shared edges of several triangles
                    Triangle t = mesh.get(r.nextInt(mesh.size()));
                    p = rnd(r, -1, 1).normalize().times(15);
                    d = (r.nextBoolean() ? t.a : t.b).minus(p);
                }
                case 3 -> { // axis-parallel
                    p = rnd(r, -6, 6);
                    int axis = r.nextInt(3);
                    double s = r.nextBoolean() ? 1 : -1;
                    d = new Vec3(axis == 0 ? s : 0.0, axis == 1 ? s : -0.0, axis == 2 ? s : 0.0);
                }
                default -> { // aimed at an edge's midpoint
                    Triangle t = mesh.get(r.nextInt(mesh.size()));
                    p = rnd(r, -10, 10);
                    d = t.a.plus(t.c).times(0.5).minus(p);
                }
            }
            rays.add(i % 3 == 0 ? new Ray(p, d, r.nextDouble(0, 0.3), r.nextDouble(0.3, 2)) : new Ray(p, d));
        }
        return rays;
    }

    /** The oracle: every triangle in file order, each with its own intersect. */
    static int linear(List<Triangle> mesh, IntersectionRecord rec, Ray ray) {
        int found = -1;
        for (int i = 0; i < mesh.size(); i++) {
            if (mesh.get(i).intersect(rec, ray)) {
                found = i;
            }
        }
        return found;
    }

    /** The mesh of seed s scaled by 2^e and moved by o (exact for powers of two and small o). */
    static List<Triangle> scaled(List<Triangle> tris, int e, Vec3 o) {
        List<Triangle> out = new ArrayList<>();
        for (Triangle t : tris) {
            out.add(new Triangle(move(t.a, e, o), move(t.b, e, o), move(t.c, e, o), M, t.name()));
        }
        return out;
    }

    static Vec3 move(Vec3 v, int e, Vec3 o) {
        return new Vec3(Math.scalb(v.x, e) + o.x, Math.scalb(v.y, e) + o.y, Math.scalb(v.z, e) + o.z);
    }

    /**
     * Rays that stress the float traversal's widened bounds: grazing a triangle's plane, along a
     * shared edge (from a point on its line), from far away (10⁶ to 10¹² times the mesh, and
     * beyond the float range), starting on a box plane or a vertex (t = 0 hits), and tiny
     * direction components.
     */
    static List<Ray> stressRays(long seed, List<Triangle> mesh, int n) {
        SplittableRandom r = new SplittableRandom(seed * 104729 + 3);
        BoundingBox box = new Mesh(mesh, "box").boundingBox();
        double size = box.max.minus(box.min).length();
        Vec3 mid = box.min.plus(box.max).times(0.5);
        List<Ray> rays = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Triangle t = mesh.get(r.nextInt(mesh.size()));
            Vec3 u = t.b.minus(t.a);
            Vec3 w = t.c.minus(t.a);
            Vec3 nrm = u.cross(w);
            Vec3 inside = t.a.plus(u.times(r.nextDouble(0, 0.5))).plus(w.times(r.nextDouble(0, 0.5)));
            Vec3 p;
            Vec3 d;
            switch (i % 7) {
                case 0 -> { // grazing: almost in the triangle's plane, toward a point inside it
                    Vec3 along = u.times(r.nextDouble(-1, 1)).plus(w.times(r.nextDouble(-1, 1)));
                    d = along.plus(nrm.times(Math.scalb(1.0, -r.nextInt(10, 40)) / (nrm.length() + 1e-300)));
                    p = inside.minus(d.times(r.nextDouble(0.5, 4)));
                }
                case 1 -> { // along a shared edge, from a point on its line
                    d = r.nextBoolean() ? u : w;
                    p = t.a.minus(d.times(r.nextDouble(0, 3)));
                }
                case 2 -> { // from far away, at a vertex or inside
                    double far = size * Math.pow(10, r.nextInt(6, 13));
                    p = mid.plus(rnd(r, -1, 1).normalize().times(far));
                    d = (r.nextBoolean() ? t.b : inside).minus(p);
                }
                case 3 -> { // beyond the float range: the double traversal
                    p = mid.plus(rnd(r, -1, 1).normalize().times(1e19));
                    d = inside.minus(p);
                }
                case 4 -> { // starting exactly on a vertex, or on the mesh box's planes
                    p = r.nextBoolean() ? t.c : new Vec3(box.min.x, r.nextBoolean() ? box.max.y : t.a.y, t.a.z);
                    d = rnd(r, -1, 1);
                }
                case 5 -> { // tiny and huge direction components
                    p = mid.plus(rnd(r, -1, 1).times(size));
                    d = inside.minus(p);
                    double s = Math.scalb(1.0, r.nextInt(-45, 45));
                    d = new Vec3(d.x * s, r.nextBoolean() ? d.y * 1e-12 : d.y, d.z);
                }
                default -> { // from inside the box, toward an edge midpoint
                    p = mid.plus(rnd(r, -0.3, 0.3).times(size));
                    d = t.a.plus(t.b).times(0.5).minus(p);
                }
            }
            rays.add(i % 4 == 0 ? new Ray(p, d, Double.MIN_VALUE, Math.nextDown(1.0)) : new Ray(p, d));
        }
        return rays;
    }

    /** Tree vs loop on one ray, with the tie rule; returns 1 for a hit. */
    static int agree(Mesh mesh, List<Triangle> tris, Ray ray, String ctx, int[] ties) {
        IntersectionRecord expected = new IntersectionRecord();
        IntersectionRecord actual = new IntersectionRecord();
        IntersectionRecord scratch = new IntersectionRecord();
        int want = linear(tris, expected, ray);
        boolean got = mesh.intersect(actual, ray);
        assertEquals(want >= 0, got, ctx + ": hit? loop found " + expected + ", tree " + actual);
        assertEquals(want >= 0, mesh.intersectsAny(ray, scratch), ctx + ": any hit");
        if (want < 0) {
            return 0;
        }
        assertEquals(Double.doubleToRawLongBits(expected.t), Double.doubleToRawLongBits(actual.t),
                ctx + ": t " + expected.t + " vs " + actual.t);
        if (actual.primitive != want) {
            IntersectionRecord other = new IntersectionRecord();
            assertTrue(tris.get(actual.primitive).intersect(other, ray), ctx + ": tree's triangle #"
                    + actual.primitive + " is not hit at all (loop: #" + want + ")");
            assertEquals(expected.t, other.t, ctx + ": tree's triangle #" + actual.primitive
                    + " is hit at another t than the loop's #" + want);
            assertEquals(other.point, actual.point, ctx + ": point of the tied triangle");
            ties[0]++;
        } else {
            assertEquals(expected.point, actual.point, ctx + ": point");
            assertEquals(expected.normal, actual.normal, ctx + ": normal");
        }
        return 1;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void stressRaysAgreeWithALinearLoop(long seed) {
        // The mesh as it is, tiny (2⁻⁹⁰: below the float grid's 2⁻⁷²), huge (2⁵⁰), and moved far.
        int[][] scales = {{0}, {-90}, {50}, {0}};
        Vec3[] moves = {new Vec3(0, 0, 0), new Vec3(0, 0, 0), new Vec3(0, 0, 0), new Vec3(3e6, -1e6, 2.5e6)};
        int hits = 0;
        int[] ties = {0};
        for (int v = 0; v < scales.length; v++) {
            List<Triangle> tris = scaled(randomMesh(seed), scales[v][0], moves[v]);
            Mesh mesh = new Mesh(tris, "mesh");
            assertTrue(mesh.usesPackedKernel(), "the reference Triangle: packed kernel");
            for (Ray ray : stressRays(seed + 100 * v, tris, 1500)) {
                hits += agree(mesh, tris, ray, "seed " + seed + " variant " + v + " (" + tris.size() + " triangles), "
                        + ray, ties);
            }
        }
        assertTrue(hits > 1000, "seed " + seed + ": too few hits to mean anything: " + hits);
        System.out.printf("seed %d stress: %d hits, %d on ties%n", seed, hits, ties[0]);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void theWideTraversalVisitsWhatTheDoubleOneFinds(long seed) {
        // Same triangle and t on every ray, tie or not: both traversals visit in the same order.
        List<Triangle> tris = randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        PackedTriangles engine = (PackedTriangles) mesh.packedEngine();
        IntersectionRecord a = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        List<Ray> rays = new ArrayList<>(randomRays(seed, tris, 2000));
        rays.addAll(stressRays(seed, tris, 2000));
        for (Ray ray : rays) {
            for (boolean any : new boolean[] {false, true}) {
                a.reset();
                b.reset();
                boolean hb = engine.intersectDouble(b, ray, any);
                boolean ha = engine.intersectWideWherePossible(a, ray, any);
                String ctx = "seed " + seed + " " + ray + (any ? " any hit" : " closest");
                assertEquals(hb, ha, ctx + ": hit? double " + b + ", 4-wide " + a);
                if (hb && !any) {
                    assertEquals(Double.doubleToRawLongBits(b.t), Double.doubleToRawLongBits(a.t), ctx + ": t");
                    assertEquals(b.primitive, a.primitive, ctx + ": triangle");
                }
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void packedTreeFindsWhatALinearLoopOverTrianglesFinds(long seed) {
        List<Triangle> tris = randomMesh(seed);
        Mesh mesh = new Mesh(tris, "mesh");
        assertTrue(mesh.usesPackedKernel(), "the reference Triangle: packed kernel");
        IntersectionRecord expected = new IntersectionRecord();
        IntersectionRecord actual = new IntersectionRecord();
        IntersectionRecord scratch = new IntersectionRecord();
        int hits = 0;
        int ties = 0;
        for (Ray ray : randomRays(seed, tris, 3000)) {
            String ctx = "seed " + seed + " (" + tris.size() + " triangles), " + ray;
            expected.reset();
            actual.reset();
            int want = linear(tris, expected, ray);
            boolean got = mesh.intersect(actual, ray);
            assertEquals(want >= 0, got, ctx + ": hit? loop found " + expected);
            assertEquals(want >= 0, mesh.intersectsAny(ray, scratch), ctx + ": any hit");
            if (want < 0) {
                continue;
            }
            hits++;
            assertEquals(Double.doubleToRawLongBits(expected.t), Double.doubleToRawLongBits(actual.t),
                    ctx + ": t " + expected.t + " vs " + actual.t);
            assertSame(mesh, actual.surface, ctx + ": surface");
            assertSame(M, actual.material, ctx + ": material");
            if (actual.primitive != want) {
                // Tie rule: the tree's triangle must hit at exactly the same t.
                IntersectionRecord other = new IntersectionRecord();
                assertTrue(tris.get(actual.primitive).intersect(other, ray), ctx + ": tree's triangle #"
                        + actual.primitive + " is not hit at all (loop: #" + want + ")");
                assertEquals(expected.t, other.t, ctx + ": tree's triangle #" + actual.primitive
                        + " is hit at another t than the loop's #" + want);
                assertEquals(other.point, actual.point, ctx + ": point of the tied triangle");
                assertEquals(other.normal, actual.normal, ctx + ": normal of the tied triangle");
                ties++;
            } else {
                assertEquals(expected.point, actual.point, ctx + ": point");
                assertEquals(expected.normal, actual.normal, ctx + ": normal");
            }
        }
        assertTrue(hits > 300, "seed " + seed + ": too few hits to mean anything: " + hits);
        System.out.printf("seed %d: %d hits, %d on ties (rays aimed at shared vertices and edges)%n", seed, hits, ties);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void meshesInsideASceneTreeNestTheirTraversals(long seed) {
        // A scene BVH whose primitives are meshes (trees in trees) and spheres, against a Group.
        SplittableRandom r = new SplittableRandom(seed);
        List<Surface> scene = new ArrayList<>();
        List<Triangle> all = new ArrayList<>();
        for (int m = 0; m < 4; m++) {
            List<Triangle> tris = randomMesh(seed * 10 + m);
            Vec3 shift = rnd(r, -8, 8);
            List<Triangle> moved = new ArrayList<>();
            for (Triangle t : tris) {
                moved.add(new Triangle(t.a.plus(shift), t.b.plus(shift), t.c.plus(shift), M, t.name()));
            }
            scene.add(new Mesh(moved, "mesh" + m));
            all.addAll(moved);
        }
        for (int i = 0; i < 20; i++) {
            scene.add(new Sphere(rnd(r, -10, 10), r.nextDouble(0.2, 1.5), M, "s" + i));
        }
        Bvh bvh = new Bvh(scene, "scene");
        Group group = new Group(scene, "group");
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (Ray ray : randomRays(seed, all, 2000)) {
            g.reset();
            b.reset();
            String ctx = "seed " + seed + ", " + ray;
            assertEquals(group.intersect(g, ray), bvh.intersect(b, ray), ctx + ": hit");
            assertEquals(g.t, b.t, ctx + ": t");
            assertSame(g.surface, b.surface, ctx + ": surface");
            assertEquals(group.intersectsAny(ray, g), bvh.intersectsAny(ray, b), ctx + ": any hit");
        }
    }

    /** A typical student bug: the third edge test forgotten. */
    static final class ForgetfulTriangle extends Triangle {
        ForgetfulTriangle(Triangle t) {
            super(t.a, t.b, t.c, t.material(), t.name());
        }

        @Override
        public boolean intersect(IntersectionRecord rec, Ray ray) {
            Vec3 n = b.minus(a).cross(c.minus(a));
            double dn = ray.d.dot(n);
            if (dn == 0) {
                return false;
            }
            double t = a.minus(ray.p).dot(n) / dn;
            if (!ray.inRange(t) || t >= rec.t) {
                return false;
            }
            Vec3 x = ray.evaluate(t);
            if (b.minus(a).cross(x.minus(a)).dot(n) < 0 || c.minus(b).cross(x.minus(b)).dot(n) < 0) {
                return false;
            }
            rec.set(t, x, n.normalize(), this);
            return true;
        }
    }

    @Test
    void triangleSubclassesAreTracedThroughTheirOwnIntersect() {
        List<Triangle> tris = randomMesh(4);
        List<Triangle> broken = new ArrayList<>();
        for (Triangle t : tris) {
            broken.add(new ForgetfulTriangle(t));
        }
        Mesh good = new Mesh(tris, "good");
        Mesh bad = new Mesh(broken, "bad");
        assertTrue(Mesh.PACKED_ENGINE, "this build has the packed engine and its own Triangle");
        assertTrue(good.usesPackedKernel(), "reference triangles: packed kernel");
        assertFalse(bad.usesPackedKernel(), "a subclass: the objects' own intersect");
        int differ = 0;
        IntersectionRecord g = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (Ray ray : randomRays(4, tris, 2000)) {
            g.reset();
            b.reset();
            boolean gh = good.intersect(g, ray);
            boolean bh = bad.intersect(b, ray);
            if (gh != bh || g.t != b.t) {
                differ++;
            }
            if (bh) {
                assertTrue(b.surface instanceof ForgetfulTriangle, "the hit names the student's triangle");
            }
        }
        assertTrue(differ > 20, "the bug shows in the mesh: " + differ + " of 2000 rays differ");
    }

    @Test
    void triangleListRoundTripsThroughThePackedArrays() {
        List<Triangle> tris = randomMesh(6); // with degenerate triangles
        double[] v = new double[9 * tris.size()];
        for (int i = 0; i < tris.size(); i++) {
            Triangle t = tris.get(i);
            double[] one = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z};
            System.arraycopy(one, 0, v, 9 * i, 9);
        }
        Mesh mesh = new Mesh(v, M, "soup");
        List<Triangle> back = mesh.triangles();
        assertEquals(tris.size(), back.size());
        for (int i = 0; i < tris.size(); i++) {
            assertEquals(tris.get(i).a, back.get(i).a, "triangle " + i + " a");
            assertEquals(tris.get(i).b, back.get(i).b, "triangle " + i + " b");
            assertEquals(tris.get(i).c, back.get(i).c, "triangle " + i + " c");
            assertEquals("soup triangle #" + i, back.get(i).name());
        }
        assertEquals(tris.size(), mesh.primitiveCount());
        assertTrue(mesh.packedBytes() <= 120L * tris.size(), mesh.packedBytes() + " bytes for "
                + tris.size() + " triangles");
    }

    @Test
    void tracingARayAllocatesNothingButTheHitsPointAndNormal() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        List<Triangle> tris = randomMesh(1);
        Mesh mesh = new Mesh(tris, "mesh");
        List<Ray> rays = randomRays(1, tris, 4000);
        IntersectionRecord rec = new IntersectionRecord();
        IntersectionRecord scratch = new IntersectionRecord();
        long id = Thread.currentThread().getId();
        // Warm up: the per-thread stack is made once; the JIT compiles the traversal.
        for (int k = 0; k < 20; k++) {
            for (Ray ray : rays) {
                rec.reset();
                mesh.intersect(rec, ray);
                mesh.intersectsAny(ray, scratch);
            }
        }
        // Any-hit queries name the blocker (t, surface, triangle) without vectors: zero bytes per ray.
        long before = mx.getThreadAllocatedBytes(id);
        int blocked = 0;
        for (Ray ray : rays) {
            if (mesh.intersectsAny(ray, scratch)) {
                blocked++;
            }
        }
        long anyBytes = mx.getThreadAllocatedBytes(id) - before;
        // Closest hit: only the two vectors the record holds (point and normal) per hit.
        before = mx.getThreadAllocatedBytes(id);
        int hits = 0;
        for (Ray ray : rays) {
            rec.reset();
            if (mesh.intersect(rec, ray)) {
                hits++;
            }
        }
        long closestBytes = mx.getThreadAllocatedBytes(id) - before;
        System.out.printf("allocation: any-hit %d bytes for %d rays (%d blocked); closest %d bytes for %d rays"
                + " (%d hits)%n", anyBytes, rays.size(), blocked, closestBytes, rays.size(), hits);
        assertTrue(hits > 500 && blocked > 500, "enough hits: " + hits + ", " + blocked);
        // Any allocation per ray would be at least 16 bytes a ray; allow for the few bytes the
        // measurement itself may cost.
        assertTrue(anyBytes < rays.size(), anyBytes + " bytes allocated by " + rays.size() + " any-hit queries");
        assertTrue(closestBytes <= 2L * 48 * hits + rays.size(), closestBytes + " bytes for " + hits + " hits");
        // Misses allocate nothing at all.
        before = mx.getThreadAllocatedBytes(id);
        Ray away = new Ray(new Vec3(100, 100, 100), new Vec3(1, 1, 1));
        for (int i = 0; i < 10000; i++) {
            rec.reset();
            mesh.intersect(rec, away);
            mesh.intersectsAny(away, scratch);
        }
        long missBytes = mx.getThreadAllocatedBytes(id) - before;
        assertTrue(missBytes < 10000, missBytes + " bytes allocated by 10,000 missing rays");
    }
}
