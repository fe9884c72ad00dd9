package raylab.surface;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The packed mesh engine (instructor-only: {@code assignments/release.json} keeps it out of the
 * starter, because its kernel is the triangle milestone's solution). {@link Mesh} uses it only
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
    /**
     * Inner node i's two child boxes as 12 floats from 12 i, the planes of both children side by
     * side: left min x, right min x, left min y, right min y, left min z, right min z, then the
     * max planes in the same order. Rounded outward from the doubles, and snapped outward to 0 or
     * ±2⁻⁷² when smaller than 2⁻⁷² in magnitude (see {@link #grid}).
     */
    private final float[] nodes;
    /** Inner node i's left reference at 2 i, right reference·4 + split axis at 2 i + 1. */
    private final int[] kids;
    /** Whether every plane lies within ±2⁶⁰: the float traversal's range (else doubles only). */
    private final boolean floatRange;

    /** Smallest magnitude of a nonzero plane or origin coordinate in the float traversal. */
    static final float TINY = 0x1p-72f;
    /** Largest magnitude of a plane or origin coordinate in the float traversal. */
    static final double HUGE = 0x1p60;
    /** Range of |d| components in the float traversal. */
    static final double D_MIN = 0x1p-30, D_MAX = 0x1p30;
    /**
     * Widening of exit distances: the float entry and exit are each within (1 + u)⁵ of exact
     * (u = 2⁻²⁴: the difference, d to float, 1/d, the product, the widening's own rounding), so
     * 1 + 16u covers (1 + u)⁴/(1 − u)⁵.
     */
    static final float WIDEN = 1 + 0x1p-20f;
    /** Whether rays take the float traversal when they can (-Draylab.mesh.traversal=double: never). */
    static final boolean FLOAT_TRAVERSAL = !"double".equals(System.getProperty("raylab.mesh.traversal"));

    PackedTriangles(Mesh mesh, double[] tri, BvhNodes tree, Material material) {
        this.mesh = mesh;
        this.n = tri.length / 9;
        this.tri = tri;
        this.tree = tree;
        this.material = material;
        int inners = tree.innerCount();
        nodes = new float[12 * inners];
        kids = new int[2 * inners];
        boolean range = true;
        for (int i = 0; i < inners; i++) {
            int k = BvhNodes.INNER * i;
            for (int c = 0; c < 2; c++) {
                for (int a = 0; a < 3; a++) {
                    float lo = Float.intBitsToFloat(tree.inner[k + 6 * c + a]);
                    float hi = Float.intBitsToFloat(tree.inner[k + 6 * c + 3 + a]);
                    range &= Math.abs(lo) <= HUGE && Math.abs(hi) <= HUGE;
                    nodes[12 * i + 2 * a + c] = grid(lo, false);
                    nodes[12 * i + 6 + 2 * a + c] = grid(hi, true);
                }
            }
            kids[2 * i] = tree.inner[k + 12];
            kids[2 * i + 1] = tree.inner[k + 13];
        }
        floatRange = range;
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
        return 4L * nodes.length + 4L * kids.length;
    }

    @Override
    public boolean intersect(IntersectionRecord rec, Ray ray, boolean anyHit) {
        if (n == 0) {
            return false;
        }
        if (FLOAT_TRAVERSAL && floatRange && inFloatRange(ray)) {
            return intersectFloat(rec, ray, anyHit);
        }
        return intersectDouble(rec, ray, anyHit);
    }

    /** Whether the float traversal's bounds hold for this ray (NaN fails every comparison). */
    private static boolean inFloatRange(Ray ray) {
        double dx = Math.abs(ray.d.x), dy = Math.abs(ray.d.y), dz = Math.abs(ray.d.z);
        return ray.tMin >= 0 && dx >= D_MIN && dx <= D_MAX && dy >= D_MIN && dy <= D_MAX && dz >= D_MIN && dz <= D_MAX
                && Math.abs(ray.p.x) <= HUGE && Math.abs(ray.p.y) <= HUGE && Math.abs(ray.p.z) <= HUGE;
    }

    /** The origin coordinate rounded to a float on the grid of {@link #grid}, up or down. */
    static float origin(double p, boolean up) {
        return grid(up ? BvhBuilder.up(p) : BvhBuilder.down(p), up);
    }

    /** The float t ≥ t (t ≥ 0), widened by {@link #WIDEN}, as raw bits (+∞ for +∞). */
    private static int exitBits(double t) {
        return Float.floatToRawIntBits(BvhBuilder.up(t) * WIDEN);
    }

    /**
     * Closest (or any) hit with the float traversal: slab distances in float, s·(b − o)·|1/d| with
     * s the sign of d, so that every slab distance is a product of positive factors, −0 never
     * appears, and distances ≥ 0 compare as their raw bits (as ints: branch-free max and min). An
     * origin coordinate is rounded toward the box for entry planes and away for exit planes, exit
     * distances and the closest hit are widened by {@link #WIDEN}: no box the exact ray enters
     * before the closest hit is culled, and the double watertight test at the leaves decides.
     * Negative distances (planes behind the origin) are negative ints and never win a max against
     * tMin ≥ 0, and an exit below 0 loses against every entry. Same visiting order as
     * {@link #intersectDouble}: left child first unless the ray goes toward −∞ along the split axis.
     */
    private boolean intersectFloat(IntersectionRecord rec, Ray ray, boolean anyHit) {
        final double px = ray.p.x, py = ray.p.y, pz = ray.p.z;
        final double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        final double tMin = ray.tMin, tMax = ray.tMax;
        final boolean gx = dx < 0, gy = dy < 0, gz = dz < 0;
        final int negative = (gx ? 1 : 0) | (gy ? 2 : 0) | (gz ? 4 : 0);
        // Per axis: near planes at offset a (min planes, or max ones when d < 0), far at 6 − a.
        final int nx = gx ? 6 : 0, ny = gy ? 8 : 2, nz = gz ? 10 : 4;
        final int fx = gx ? 0 : 6, fy = gy ? 2 : 8, fz = gz ? 4 : 10;
        final float sx = gx ? -1f : 1f, sy = gy ? -1f : 1f, sz = gz ? -1f : 1f;
        // −s·o with o rounded toward the box for the near side (d > 0: up) and away for the far side.
        final float qnx = -sx * origin(px, !gx), qfx = -sx * origin(px, gx);
        final float qny = -sy * origin(py, !gy), qfy = -sy * origin(py, gy);
        final float qnz = -sz * origin(pz, !gz), qfz = -sz * origin(pz, gz);
        final float ax = Math.abs(1f / (float) dx), ay = Math.abs(1f / (float) dy), az = Math.abs(1f / (float) dz);
        final float wx = ax * WIDEN, wy = ay * WIDEN, wz = az * WIDEN;
        // The search starts at t = 0, not tMin: a triangle whose plane holds p is hit at t = 0 or
        // not at all, and its computed t may straddle a small tMin (the leaf test applies tMin).
        final int tMinBits = 0;
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
        final float[] nodes = this.nodes;
        final int[] kids = this.kids;
        final int[] leaf = tree.leaf;
        final double[] tri = this.tri;
        double best = rec.t;
        if (BvhNodes.entry(tree.rootBox, 0, px, py, pz, 1.0 / dx, 1.0 / dy, 1.0 / dz, gx ? 3 : 0, gy ? 3 : 0,
                gz ? 3 : 0, 0, widen(tMax < best ? tMax : best)) == Double.POSITIVE_INFINITY) {
            return false;
        }
        int t1 = exitBits(tMax < best ? tMax : best);
        BvhNodes.Frames frames = BvhNodes.frames();
        // The packed traversal calls nothing that traces, so it may use its frame without taking it.
        BvhNodes.ensure(frames, frames.top + tree.depth + 1);
        final int[] refs = frames.refs;
        final int[] entries = frames.bits;
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
                    double t = hitT(tri, 9 * s, kx, ky, kz, shx, shy, shz, pkx, pky, pkz);
                    if (t == t) { // a hit (not NaN): the plane rule
                        t = planeRule(t, tri, 9 * s, px, py, pz);
                    }
                    // NaN (no hit) fails every comparison.
                    if (t >= tMin && t <= tMax && t < best) {
                        best = t;
                        t1 = exitBits(t);
                        bestSlot = s;
                        if (anyHit) {
                            break traversal;
                        }
                    }
                }
            } else {
                int k = 12 * ref;
                int lIn = Math.max(Math.max(bits(nodes[k + nx], sx, qnx, ax), bits(nodes[k + ny], sy, qny, ay)),
                        Math.max(bits(nodes[k + nz], sz, qnz, az), tMinBits));
                int rIn = Math.max(Math.max(bits(nodes[k + nx + 1], sx, qnx, ax), bits(nodes[k + ny + 1], sy, qny, ay)),
                        Math.max(bits(nodes[k + nz + 1], sz, qnz, az), tMinBits));
                int lOut = Math.min(Math.min(bits(nodes[k + fx], sx, qfx, wx), bits(nodes[k + fy], sy, qfy, wy)),
                        Math.min(bits(nodes[k + fz], sz, qfz, wz), t1));
                int rOut = Math.min(Math.min(bits(nodes[k + fx + 1], sx, qfx, wx), bits(nodes[k + fy + 1], sy, qfy, wy)),
                        Math.min(bits(nodes[k + fz + 1], sz, qfz, wz), t1));
                int packed = kids[2 * ref + 1];
                boolean rightFirst = (negative >> (packed & 3) & 1) != 0;
                boolean hitL = lIn <= lOut;
                boolean hitR = rIn <= rOut;
                int left = kids[2 * ref];
                int right = packed >> 2;
                if (hitL & hitR) {
                    refs[top] = rightFirst ? left : right;
                    entries[top++] = rightFirst ? lIn : rIn;
                    ref = rightFirst ? right : left;
                    continue;
                }
                if (hitL) {
                    ref = left;
                    continue;
                }
                if (hitR) {
                    ref = right;
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
        return finish(rec, anyHit, best, bestSlot, tests, kx, ky, kz, shx, shy, shz, pkx, pky, pkz);
    }

    /** t moved away from 0 by 2γ3·|t|: above the rounding of a computed entry distance. */
    private static double widen(double t) {
        return t + Math.abs(t) * (BvhNodes.ROUND_UP - 1);
    }

    /** The slab distance s·(b − o)·a (s = ±1, q = −s·o, a = |1/d|, perhaps widened) as raw bits. */
    private static int bits(float b, float s, float q, float a) {
        return Float.floatToRawIntBits(Math.fma(b, s, q) * a);
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
        // The search starts at 0 (or below a negative tMin), as in intersectFloat.
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
    private static double planeRule(double t, double[] tri, int o, double px, double py, double pz) {
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
