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

    PackedTriangles(Mesh mesh, double[] tri, BvhNodes tree, Material material) {
        this.mesh = mesh;
        this.n = tri.length / 9;
        this.tri = tri;
        this.tree = tree;
        this.material = material;
    }

    @Override
    public long bytes() {
        return 0;
    }

    /** Closest (or any) hit through the tree with the packed kernel; allocates only for a hit. */
    @Override
    public boolean intersect(IntersectionRecord rec, Ray ray, boolean anyHit) {
        if (n == 0) {
            return false;
        }
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
        double t1 = tMax < best ? tMax : best; // the far end of the search: min(tMax, closest hit)
        if (BvhNodes.entry(tree.rootBox, 0, px, py, pz, ix, iy, iz, nx, ny, nz, tMin, t1)
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
                    // NaN (no hit) fails every comparison.
                    if (t >= tMin && t <= tMax && t < best) {
                        best = t;
                        t1 = t;
                        bestSlot = s;
                        if (anyHit) {
                            break traversal;
                        }
                    }
                }
            } else {
                int k = BvhNodes.INNER * ref;
                double tl = BvhNodes.entry(inner, k, px, py, pz, ix, iy, iz, ux, uy, uz, nx, ny, nz, tMin, t1);
                double tr = BvhNodes.entry(inner, k + 6, px, py, pz, ix, iy, iz, ux, uy, uz, nx, ny, nz, tMin, t1);
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
        if (t < 0 && -t <= zeroBound(ax, ay, sz * az, bx, by, sz * bz, cx, cy, sz * cz, e0, e1, e2, det, sz)) {
            t = 0; // p lies in the plane up to rounding: the hit at t = 0 counts (docs/shading.md)
        }
        return t;
    }

    /** Triangle's bound on |t| when the exact t is 0, with its operations in its order. */
    private static double zeroBound(double ax, double ay, double az, double bx, double by, double bz, double cx,
            double cy, double cz, double e0, double e1, double e2, double det, double sz) {
        double x = Math.max(Math.max(Math.abs(ax), Math.abs(bx)), Math.abs(cx));
        double y = Math.max(Math.max(Math.abs(ay), Math.abs(by)), Math.abs(cy));
        double zs = Math.max(Math.max(Math.abs(az), Math.abs(bz)), Math.abs(cz));
        double z = zs / Math.abs(sz);
        double e = Math.max(Math.max(Math.abs(e0), Math.abs(e1)), Math.abs(e2));
        double dx = GAMMA5 * (x + z);
        double dy = GAMMA5 * (y + z);
        double de = 2 * (GAMMA2 * x * y + dy * x + dx * y);
        return 6 * (GAMMA3 * e * zs + de * zs + GAMMA3 * zs * e) / Math.abs(det);
    }

    private static final double EPS = 0x1p-53;
    private static final double GAMMA2 = 2 * EPS / (1 - 2 * EPS);
    private static final double GAMMA3 = 3 * EPS / (1 - 3 * EPS);
    private static final double GAMMA5 = 5 * EPS / (1 - 5 * EPS);

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
