package raylab.mesh;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.BvhNodes;
import raylab.surface.Mesh;
import raylab.surface.Triangle;

/**
 * The packed mesh engine (instructor-only: the mesh engine module, which the starter does not
 * have, because its kernel is the triangle milestone's solution). {@link Mesh} uses it only
 * when this class, {@code Mesh} and {@code Triangle} come from one code source, so a student's
 * {@code Triangle} is never replaced by it (docs/mesh-engine.md).
 *
 * <p>The kernel is the reference {@link Triangle#intersect} (watertight test) rewritten on the
 * packed arrays with the same operations in the same order, so that it finds the same hits with
 * the same t, bit for bit; {@code record} rebuilds the point and the normal in {@code Vec3}'s
 * order of operations.
 */
final class PackedTriangles implements Mesh.Engine {
    private final Mesh mesh;
    private final int n;
    /** Triangle at leaf slot s: a, b, c at tri[9 s .. 9 s + 9); degenerate ones collapsed to a. */
    private final double[] tri;
    private final BvhNodes tree;
    private final Material material;
    /** Smallest magnitude of a nonzero box plane in the float traversal (see {@link #grid}). */
    static final float TINY = 0x1p-72f;
    /** Largest magnitude of a box plane or origin coordinate in the float traversal. */
    static final double HUGE = 0x1p60;
    /** Range of |d| components in the float traversal. */
    static final double D_MIN = 0x1p-30, D_MAX = 0x1p30;
    /**
     * Whether rays take the 4-wide float traversal where its bounds hold (the default), or the
     * double traversal always (-Draylab.mesh.traversal=double).
     */
    static final boolean WIDE_TRAVERSAL = !"double".equals(System.getProperty("raylab.mesh.traversal"));
    /**
     * The Vector API traversal when asked for (-Draylab.mesh.traversal=vector) and to be had, else
     * null: the scalar {@link PackedOctants}.
     */
    static final VectorTraversal VECTOR = VectorTraversal.fromProperty();
    /** The 4-wide tree of the octant traversal. */
    private final PackedWide wide;

    PackedTriangles(Mesh mesh, double[] tri, BvhNodes tree, Material material) {
        this.mesh = mesh;
        this.n = tri.length / 9;
        this.tri = tri;
        this.tree = tree;
        this.material = material;
        wide = new PackedWide(tree);
    }

    /**
     * f moved outward (up when {@code up}) onto 0 or ±2⁻⁷² if it is nonzero and smaller in
     * magnitude, so that the difference of two such floats is 0 or at least 2⁻⁹⁵ in magnitude and
     * slab distances are never subnormal. Also turns −0 into +0.
     */
    static float grid(float f, boolean up) {
        if (Math.abs(f) >= TINY) {
            return f;
        }
        if (f == 0) {
            return 0f;
        }
        return up ? (f > 0 ? TINY : 0f) : (f > 0 ? 0f : -TINY);
    }

    @Override
    public long bytes() {
        return wide.bytes();
    }

    @Override
    public String traversal() {
        if (!WIDE_TRAVERSAL) {
            return "double traversal";
        }
        return (VECTOR == null ? "4-wide scalar" : "4-wide Vector API") + " traversal where the float bounds hold";
    }

    @Override
    public boolean intersect(IntersectionRecord rec, Ray ray, boolean anyHit) {
        if (n == 0) {
            return false;
        }
        if (WIDE_TRAVERSAL && wide.inRange && inFloatRange(ray)) {
            return intersectWide(rec, ray, anyHit, VECTOR);
        }
        return intersectDouble(rec, ray, anyHit);
    }

    /** Whether the ray takes the 4-wide traversal (by default, and when its bounds hold). */
    boolean takesWide(Ray ray) {
        return WIDE_TRAVERSAL && n > 0 && wide.inRange && inFloatRange(ray);
    }

    /** The binary tree (for tests). */
    BvhNodes tree() {
        return tree;
    }

    /** The 4-wide tree (for tests). */
    PackedWide wide() {
        return wide;
    }

    /** The 4-wide traversal where its bounds hold, else the double one (for tests and benchmarks). */
    boolean intersectWideWherePossible(IntersectionRecord rec, Ray ray, boolean anyHit) {
        return intersectWideWith(VECTOR, rec, ray, anyHit);
    }

    /**
     * The 4-wide traversal with {@code vector} (null: the scalar one) where its bounds hold, else the
     * double one (for tests).
     */
    boolean intersectWideWith(VectorTraversal vector, IntersectionRecord rec, Ray ray, boolean anyHit) {
        if (n == 0) {
            return false;
        }
        return wide.inRange && inFloatRange(ray) ? intersectWide(rec, ray, anyHit, vector) : intersectDouble(rec, ray, anyHit);
    }

    /**
     * Closest (or any) hit with the 4-wide float traversal ({@link PackedOctants}, one copy per ray
     * octant), or with {@code vector} when not null, for rays within the float bounds ({@link #inFloatRange}).
     */
    private boolean intersectWide(IntersectionRecord rec, Ray ray, boolean anyHit, VectorTraversal vector) {
        final double px = ray.p.x, py = ray.p.y, pz = ray.p.z;
        final double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        final boolean gx = dx < 0, gy = dy < 0, gz = dz < 0;
        final int octant = (gx ? 1 : 0) | (gy ? 2 : 0) | (gz ? 4 : 0);
        // Slab distance (o' − b)·m with m = −1/d in float and o' a float strictly on the safe side of o:
        // for near planes above o when d > 0 (below when d < 0), for far ones the other way round, so
        // that no computed near distance exceeds the exact one and no far one falls short of it.
        final float mx = -(float) (1.0 / dx), my = -(float) (1.0 / dy), mz = -(float) (1.0 / dz);
        final float lx = PackedWide.below(px), hx = PackedWide.above(px);
        final float ly = PackedWide.below(py), hy = PackedWide.above(py);
        final float lz = PackedWide.below(pz), hz = PackedWide.above(pz);
        final float onx = gx ? lx : hx, ofx = gx ? hx : lx;
        final float ony = gy ? ly : hy, ofy = gy ? hy : ly;
        final float onz = gz ? lz : hz, ofz = gz ? hz : lz;
        // Ray space of the watertight test, as in Triangle.intersect.
        final int kz = largestAxis(dx, dy, dz);
        final int kx = kz == 2 ? 0 : kz + 1;
        final int ky = kx == 2 ? 0 : kx + 1;
        final double dkx = kx == 0 ? dx : kx == 1 ? dy : dz;
        final double dky = ky == 0 ? dx : ky == 1 ? dy : dz;
        final double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        final double shx = -dkx / dkz, shy = -dky / dkz, shz = 1 / dkz;
        final double pkx = kx == 0 ? px : kx == 1 ? py : pz;
        final double pky = ky == 0 ? px : ky == 1 ? py : pz;
        final double pkz = kz == 0 ? px : kz == 1 ? py : pz;
        BvhNodes.Frames frames = BvhNodes.frames();
        // Each node pushes at most four children and pops one. The 4-wide traversal traces nothing
        // else, so its stack of pending children starts at 0 whatever frames the caller has taken.
        BvhNodes.ensure(frames, 3 * tree.depth + 8);
        final double[] r = frames.ray;
        r[PackedWide.PX] = px;
        r[PackedWide.PY] = py;
        r[PackedWide.PZ] = pz;
        r[PackedWide.TMIN] = ray.tMin;
        r[PackedWide.TMAX] = ray.tMax;
        r[PackedWide.BEST] = rec.t;
        r[PackedWide.SHX] = shx;
        r[PackedWide.SHY] = shy;
        r[PackedWide.SHZ] = shz;
        r[PackedWide.PKX] = pkx;
        r[PackedWide.PKY] = pky;
        r[PackedWide.PKZ] = pkz;
        r[PackedWide.TESTS] = 0;
        int slot = vector == null
                ? PackedOctants.trace(octant, wide, tree.leaf, tri, frames.pending, r, kz, onx, ony, onz, ofx, ofy,
                        ofz, mx, my, mz, anyHit)
                : vector.trace(octant, wide, tree.leaf, tri, frames.pending, r, kz, onx, ony, onz, ofx, ofy, ofz,
                        mx, my, mz, anyHit, frames.lanes);
        return finish(rec, anyHit, r[PackedWide.BEST], slot, (int) r[PackedWide.TESTS], kx, ky, kz, shx, shy, shz, pkx,
                pky, pkz);
    }

    /** Whether the float traversal's bounds hold for this ray (NaN fails every comparison). */
    private static boolean inFloatRange(Ray ray) {
        double dx = Math.abs(ray.d.x), dy = Math.abs(ray.d.y), dz = Math.abs(ray.d.z);
        return ray.tMin >= 0 && dx >= D_MIN && dx <= D_MAX && dy >= D_MIN && dy <= D_MAX && dz >= D_MIN && dz <= D_MAX
                && Math.abs(ray.p.x) <= HUGE && Math.abs(ray.p.y) <= HUGE && Math.abs(ray.p.z) <= HUGE;
    }

    /** t moved away from 0 by 2γ3·|t|: above the rounding of a computed entry distance. */
    private static double widen(double t) {
        return t + Math.abs(t) * (BvhNodes.ROUND_UP - 1);
    }

    private boolean finish(IntersectionRecord rec, boolean anyHit, double best, int bestSlot, int tests, int kx,
            int ky, int kz, double sx, double sy, double sz, double pkx, double pky, double pkz) {
        rec.tests += tests;
        if (bestSlot < 0) {
            return false;
        }
        if (anyHit) {
            // A shadow ray needs only to know the blocker: no point or normal, nothing allocated.
            rec.t = best;
            rec.point = null;
            rec.normal = null;
            rec.surface = mesh;
            rec.material = material;
            rec.primitive = tree.order[bestSlot];
            return true;
        }
        record(rec, best, bestSlot, kx, ky, kz, sx, sy, sz, pkx, pky, pkz);
        return true;
    }

    /**
     * Closest (or any) hit with the double traversal (BvhNodes' int[] nodes, slabs in double): for
     * rays outside the float traversal's bounds (a zero or extreme direction component, a huge
     * origin, tMin &lt; 0).
     */
    boolean intersectDouble(IntersectionRecord rec, Ray ray, boolean anyHit) {
        final double px = ray.p.x, py = ray.p.y, pz = ray.p.z;
        final double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        final double tMin = ray.tMin, tMax = ray.tMax;
        final double ix = 1.0 / dx, iy = 1.0 / dy, iz = 1.0 / dz;
        final int nx = ix < 0 ? 3 : 0, ny = iy < 0 ? 3 : 0, nz = iz < 0 ? 3 : 0;
        final double ux = ix * BvhNodes.ROUND_UP, uy = iy * BvhNodes.ROUND_UP, uz = iz * BvhNodes.ROUND_UP;
        final int negative = (nx != 0 ? 1 : 0) | (ny != 0 ? 2 : 0) | (nz != 0 ? 4 : 0);
        // Ray space of the watertight test, as in Triangle.intersect.
        final int kz = largestAxis(dx, dy, dz);
        final int kx = kz == 2 ? 0 : kz + 1;
        final int ky = kx == 2 ? 0 : kx + 1;
        final double dkx = kx == 0 ? dx : kx == 1 ? dy : dz;
        final double dky = ky == 0 ? dx : ky == 1 ? dy : dz;
        final double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        final double sx = -dkx / dkz, sy = -dky / dkz, sz = 1 / dkz;
        final double pkx = kx == 0 ? px : kx == 1 ? py : pz;
        final double pky = ky == 0 ? px : ky == 1 ? py : pz;
        final double pkz = kz == 0 ? px : kz == 1 ? py : pz;
        final int[] inner = tree.inner;
        final int[] leaf = tree.leaf;
        final double[] tri = this.tri;
        double best = rec.t;
        // The far end of the search, min(tMax, closest hit), widened: a computed entry distance
        // may exceed the exact one by its rounding (γ3), and a hit exactly at tMax must be seen.
        double t1 = widen(tMax < best ? tMax : best);
        // The search starts at 0 (or below a negative tMin), as in the 4-wide traversal.
        final double t0 = tMin > 0 ? 0 : tMin - Math.abs(tMin) * (BvhNodes.ROUND_UP - 1);
        if (BvhNodes.entry(tree.rootBox, 0, px, py, pz, ix, iy, iz, nx, ny, nz, t0, t1)
                == Double.POSITIVE_INFINITY) {
            return false;
        }
        BvhNodes.Frames frames = BvhNodes.frames();
        // The packed traversal calls nothing that traces, so it may use its frame without taking it.
        BvhNodes.ensure(frames, frames.top + tree.depth + 1);
        final int[] refs = frames.refs;
        final double[] entries = frames.entry;
        final int base = frames.top;
        int top = base;
        int ref = tree.rootRef;
        int bestSlot = -1;
        int tests = 0;
        traversal:
        while (true) {
            if (ref < 0) {
                int l = 2 * ~ref;
                int end = leaf[l] + leaf[l + 1];
                for (int s = leaf[l]; s < end; s++) {
                    tests++;
                    double t = hitT(tri, 9 * s, kx, ky, kz, sx, sy, sz, pkx, pky, pkz);
                    if (t == t) { // a hit (not NaN): the plane rule
                        t = planeRule(t, tri, 9 * s, px, py, pz);
                    }
                    // NaN (no hit) fails every comparison.
                    if (t >= tMin && t <= tMax && t < best) {
                        best = t;
                        t1 = widen(t);
                        bestSlot = s;
                        if (anyHit) {
                            break traversal;
                        }
                    }
                }
            } else {
                int k = BvhNodes.INNER * ref;
                double tl = BvhNodes.entry(inner, k, px, py, pz, ix, iy, iz, ux, uy, uz, nx, ny, nz, t0, t1);
                double tr = BvhNodes.entry(inner, k + 6, px, py, pz, ix, iy, iz, ux, uy, uz, nx, ny, nz, t0, t1);
                int packed = inner[k + 13];
                boolean rightFirst = (negative >> (packed & 3) & 1) != 0;
                int near = rightFirst ? packed >> 2 : inner[k + 12];
                int far = rightFirst ? inner[k + 12] : packed >> 2;
                double tNear = rightFirst ? tr : tl;
                double tFar = rightFirst ? tl : tr;
                if (tNear != Double.POSITIVE_INFINITY) {
                    if (tFar != Double.POSITIVE_INFINITY) {
                        refs[top] = far;
                        entries[top++] = tFar;
                    }
                    ref = near;
                    continue;
                }
                if (tFar != Double.POSITIVE_INFINITY) {
                    ref = far;
                    continue;
                }
            }
            while (true) {
                if (top == base) {
                    break traversal;
                }
                top--;
                if (entries[top] <= t1) {
                    ref = refs[top];
                    break;
                }
            }
        }
        return finish(rec, anyHit, best, bestSlot, tests, kx, ky, kz, sx, sy, sz, pkx, pky, pkz);
    }

    private static int largestAxis(double dx, double dy, double dz) {
        double x = Math.abs(dx);
        double y = Math.abs(dy);
        double z = Math.abs(dz);
        return x > y && x > z ? 0 : y > z ? 1 : 2;
    }

    /**
     * The packed kernel: the watertight test of Triangle.intersect on the triangle at
     * {@code tri[o .. o + 9)}, for a ray already in ray space (axes kx, ky, kz, shear sx, sy, sz,
     * origin components pkx, pky, pkz). Returns t, or NaN when the ray misses the triangle or lies
     * in its plane. Range checks are the caller's.
     */
    static double hitT(double[] tri, int o, int kx, int ky, int kz, double sx, double sy, double sz,
            double pkx, double pky, double pkz) {
        double az = tri[o + kz] - pkz;
        double ax = tri[o + kx] - pkx + sx * az;
        double ay = tri[o + ky] - pky + sy * az;
        double bz = tri[o + 3 + kz] - pkz;
        double bx = tri[o + 3 + kx] - pkx + sx * bz;
        double by = tri[o + 3 + ky] - pky + sy * bz;
        double cz = tri[o + 6 + kz] - pkz;
        double cx = tri[o + 6 + kx] - pkx + sx * cz;
        double cy = tri[o + 6 + ky] - pky + sy * cz;
        double e0 = differenceOfProducts(bx, cy, by, cx);
        double e1 = differenceOfProducts(cx, ay, cy, ax);
        // Two edge functions of opposite signs already decide the miss; the third is not needed.
        if (e0 < 0 && e1 > 0 || e0 > 0 && e1 < 0) {
            return Double.NaN;
        }
        double e2 = differenceOfProducts(ax, by, ay, bx);
        if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) {
            return Double.NaN;
        }
        double det = e0 + e1 + e2;
        if (det == 0) {
            return Double.NaN;
        }
        double t = e0 / det * (sz * az) + e1 / det * (sz * bz) + e2 / det * (sz * cz);
        return t;
    }

    /**
     * Triangle.intersect's rule for a ray whose origin lies in the triangle's plane (up to
     * rounding): t = 0 if p is in the triangle's box, else no hit (NaN). Kept out of hitT so that
     * hitT stays small enough to be inlined.
     */
    static double planeRule(double t, double[] tri, int o, double px, double py, double pz) {
        if (!inPlane(tri, o, px, py, pz)) {
            return t;
        }
        return inBox(tri, o, px, py, pz) ? 0 : Double.NaN;
    }

    /** Triangle.inPlane on the triangle at tri[o ..), with its operations in its order. */
    private static boolean inPlane(double[] tri, int o, double px, double py, double pz) {
        double ux = tri[o + 3] - tri[o], uy = tri[o + 4] - tri[o + 1], uz = tri[o + 5] - tri[o + 2];
        double vx = tri[o + 6] - tri[o], vy = tri[o + 7] - tri[o + 1], vz = tri[o + 8] - tri[o + 2];
        double wx = tri[o] - px, wy = tri[o + 1] - py, wz = tri[o + 2] - pz;
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        double s = wx * nx + wy * ny + wz * nz;
        double ax = Math.abs(uy * vz) + Math.abs(uz * vy);
        double ay = Math.abs(uz * vx) + Math.abs(ux * vz);
        double az = Math.abs(ux * vy) + Math.abs(uy * vx);
        double bound = GAMMA8 * (Math.abs(wx) * (Math.abs(nx) + ax) + Math.abs(wy) * (Math.abs(ny) + ay)
                + Math.abs(wz) * (Math.abs(nz) + az));
        double size = Math.abs(nx) + Math.abs(ny) + Math.abs(nz);
        return Math.abs(s) <= bound && size > GAMMA8 * (ax + ay + az);
    }

    /** Whether p lies in the bounding box of the triangle at tri[o ..) (closed). */
    private static boolean inBox(double[] t, int o, double px, double py, double pz) {
        return px >= Math.min(Math.min(t[o], t[o + 3]), t[o + 6]) && px <= Math.max(Math.max(t[o], t[o + 3]), t[o + 6])
                && py >= Math.min(Math.min(t[o + 1], t[o + 4]), t[o + 7])
                && py <= Math.max(Math.max(t[o + 1], t[o + 4]), t[o + 7])
                && pz >= Math.min(Math.min(t[o + 2], t[o + 5]), t[o + 8])
                && pz <= Math.max(Math.max(t[o + 2], t[o + 5]), t[o + 8]);
    }

    private static final double GAMMA8 = 8 * 0x1p-53 / (1 - 8 * 0x1p-53);

    /** Writes the hit on the triangle at leaf slot s to the record, as Triangle.intersect does. */
    private void record(IntersectionRecord rec, double t, int s, int kx, int ky, int kz, double sx,
            double sy, double sz, double pkx, double pky, double pkz) {
        int o = 9 * s;
        double az = tri[o + kz] - pkz;
        double ax = tri[o + kx] - pkx + sx * az;
        double ay = tri[o + ky] - pky + sy * az;
        double bz = tri[o + 3 + kz] - pkz;
        double bx = tri[o + 3 + kx] - pkx + sx * bz;
        double by = tri[o + 3 + ky] - pky + sy * bz;
        double cz = tri[o + 6 + kz] - pkz;
        double cx = tri[o + 6 + kx] - pkx + sx * cz;
        double cy = tri[o + 6 + ky] - pky + sy * cz;
        double e0 = differenceOfProducts(bx, cy, by, cx);
        double e1 = differenceOfProducts(cx, ay, cy, ax);
        double e2 = differenceOfProducts(ax, by, ay, bx);
        double det = e0 + e1 + e2;
        double b0 = e0 / det;
        double b1 = e1 / det;
        double b2 = e2 / det;
        // x = a·b0 + b·b1 + c·b2 and n = (b − a) × (c − a) / ‖…‖, in Vec3's order of operations.
        Vec3 x = new Vec3(tri[o] * b0 + tri[o + 3] * b1 + tri[o + 6] * b2,
                tri[o + 1] * b0 + tri[o + 4] * b1 + tri[o + 7] * b2,
                tri[o + 2] * b0 + tri[o + 5] * b1 + tri[o + 8] * b2);
        double ux = tri[o + 3] - tri[o], uy = tri[o + 4] - tri[o + 1], uz = tri[o + 5] - tri[o + 2];
        double vx = tri[o + 6] - tri[o], vy = tri[o + 7] - tri[o + 1], vz = tri[o + 8] - tri[o + 2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        double inv = 1.0 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        rec.t = t;
        rec.point = x;
        rec.normal = new Vec3(nx * inv, ny * inv, nz * inv);
        rec.surface = mesh;
        rec.material = material;
        rec.primitive = tree.order[s];
    }

    /** a·b − c·d accurate to 2 ulps (Kahan's algorithm), as in Triangle. */
    private static double differenceOfProducts(double a, double b, double c, double d) {
        double cd = c * d;
        double error = Math.fma(-c, d, cd);
        return Math.fma(a, b, -cd) + error;
    }

}
