package raylab.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A triangle mesh, such as one loaded from an OBJ file: its triangles share one material and are
 * traced through their own bounding volume hierarchy.
 *
 * <p>Storage is packed: the vertices of all triangles in one {@code double[]} (nine numbers per
 * triangle, in the tree's leaf order) and the tree in one {@code int[]} ({@link BvhNodes}), about
 * 92 bytes per triangle and no object per triangle or node. The leaf test is one of two kernels
 * over the same tree (docs/mesh-engine.md):
 * <ul>
 * <li>the packed kernel, the reference {@link Triangle#intersect} (watertight test) rewritten on
 * the packed arrays with the same operations in the same order, so that it finds the same hits
 * with the same t, bit for bit;</li>
 * <li>the student kernel: the {@link Triangle} objects' own {@code intersect}. It is used when
 * the class {@code Triangle} is not the reference (its solution region, with the marker the
 * packed kernel relies on, has been replaced by a student's code), or when the mesh was given
 * triangles of a subclass. A bug in a student's {@code Triangle.intersect} therefore shows in
 * every mesh.</li>
 * </ul>
 */
public final class Mesh extends Surface {
    /**
     * Whether the class Triangle is the reference one: its solution region declares the field
     * {@code REFERENCE_KERNEL}, which a starter (and so a student's file) does not have.
     */
    public static final boolean REFERENCE_TRIANGLE = hasReferenceMarker(Triangle.class);

    private final int n;
    /** Triangle at leaf slot s: a, b, c at tri[9 s .. 9 s + 9); degenerate ones collapsed to a. */
    private final double[] tri;
    private final BvhNodes tree;
    private final BoundingBox box;
    /** The triangle objects in leaf order when the student kernel is used, else null. */
    private final Triangle[] objects;
    private final Material material;
    /** File order → triangles, given or made on first request. */
    private volatile List<Triangle> fileOrder;
    /** Original vertices of degenerate triangles (zero normal), by file index. */
    private final Map<Integer, double[]> degenerate = new HashMap<>();

    /** A mesh of the given triangles (file order), which share the first one's material. */
    public Mesh(List<Triangle> triangles, String name) {
        this(vertices(triangles), triangles.isEmpty() ? null : triangles.get(0).material(), name,
                List.copyOf(triangles));
    }

    /**
     * A mesh of {@code vertices.length / 9} triangles given as a, b, c (nine numbers each, file
     * order), all with the given material. Triangle i is named "NAME triangle #i".
     */
    public Mesh(double[] vertices, Material material, String name) {
        this(vertices, material, name, null);
    }

    private Mesh(double[] vertices, Material material, String name, List<Triangle> given) {
        super(material, name);
        this.material = material;
        if (vertices.length % 9 != 0) {
            throw new IllegalArgumentException("nine numbers per triangle expected, got " + vertices.length);
        }
        n = vertices.length / 9;
        double[] boxes = new double[6 * n];
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = 0; i < n; i++) {
            int v = 9 * i;
            for (int k = 0; k < 3; k++) {
                // As Triangle.boundingBox(): a.min(b).min(c), a.max(b).max(c).
                double lo = Math.min(Math.min(vertices[v + k], vertices[v + 3 + k]), vertices[v + 6 + k]);
                double hi = Math.max(Math.max(vertices[v + k], vertices[v + 3 + k]), vertices[v + 6 + k]);
                boxes[6 * i + k] = lo;
                boxes[6 * i + 3 + k] = hi;
            }
            x0 = Math.min(x0, boxes[6 * i]);
            y0 = Math.min(y0, boxes[6 * i + 1]);
            z0 = Math.min(z0, boxes[6 * i + 2]);
            x1 = Math.max(x1, boxes[6 * i + 3]);
            y1 = Math.max(y1, boxes[6 * i + 4]);
            z1 = Math.max(z1, boxes[6 * i + 5]);
        }
        tree = BvhBuilder.build(boxes, n);
        boxes = null;
        tri = new double[9 * n];
        for (int s = 0; s < n; s++) {
            int f = tree.order[s];
            System.arraycopy(vertices, 9 * f, tri, 9 * s, 9);
            if (isDegenerate(tri, 9 * s)) {
                degenerate.put(f, java.util.Arrays.copyOfRange(vertices, 9 * f, 9 * f + 9));
                // All three vertices equal: every edge function is exactly 0, so det = 0 and the
                // kernel reports no hit, as Triangle.intersect does for a zero normal.
                System.arraycopy(tri, 9 * s, tri, 9 * s + 3, 3);
                System.arraycopy(tri, 9 * s, tri, 9 * s + 6, 3);
            }
        }
        box = n == 0 ? BoundingBox.EMPTY : new BoundingBox(new Vec3(x0, y0, z0), new Vec3(x1, y1, z1));
        fileOrder = given;
        boolean student = !REFERENCE_TRIANGLE;
        if (given != null) {
            for (Triangle t : given) {
                student |= t.getClass() != Triangle.class;
            }
        }
        if (student) {
            List<Triangle> all = triangles();
            objects = new Triangle[n];
            for (int s = 0; s < n; s++) {
                objects[s] = all.get(tree.order[s]);
            }
        } else {
            objects = null;
        }
    }

    private static double[] vertices(List<Triangle> triangles) {
        double[] v = new double[9 * triangles.size()];
        int k = 0;
        for (Triangle t : triangles) {
            for (Vec3 p : new Vec3[] {t.a, t.b, t.c}) {
                v[k++] = p.x;
                v[k++] = p.y;
                v[k++] = p.z;
            }
        }
        return v;
    }

    private static boolean hasReferenceMarker(Class<?> c) {
        try {
            c.getDeclaredField("REFERENCE_KERNEL");
            return true;
        } catch (NoSuchFieldException e) {
            return false;
        }
    }

    /** Whether (b − a) × (c − a) is the zero vector, computed as Triangle.intersect does. */
    private static boolean isDegenerate(double[] t, int o) {
        double ux = t[o + 3] - t[o], uy = t[o + 4] - t[o + 1], uz = t[o + 5] - t[o + 2];
        double vx = t[o + 6] - t[o], vy = t[o + 7] - t[o + 1], vz = t[o + 8] - t[o + 2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        return nx == 0 && ny == 0 && nz == 0;
    }

    /** Whether rays are tested against the packed reference kernel (else the Triangle objects). */
    public boolean usesPackedKernel() {
        return objects == null;
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        if (objects != null) {
            return tree.traverse(outRecord, ray, objects, false);
        }
        return packed(outRecord, ray, false);
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        scratch.reset();
        if (objects != null) {
            return tree.traverse(scratch, ray, objects, true);
        }
        return packed(scratch, ray, true);
    }

    /** Closest (or any) hit through the tree with the packed kernel; allocates only for a hit. */
    private boolean packed(IntersectionRecord rec, Ray ray, boolean anyHit) {
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
            rec.surface = this;
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
        return e0 / det * (sz * az) + e1 / det * (sz * bz) + e2 / det * (sz * cz);
    }

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
        rec.surface = this;
        rec.material = material;
        rec.primitive = tree.order[s];
    }

    /** a·b − c·d accurate to 2 ulps (Kahan's algorithm), as in Triangle. */
    private static double differenceOfProducts(double a, double b, double c, double d) {
        double cd = c * d;
        double error = Math.fma(-c, d, cd);
        return Math.fma(a, b, -cd) + error;
    }

    @Override
    public BoundingBox boundingBox() {
        return box;
    }

    @Override
    public int primitiveCount() {
        return n;
    }

    /** Number of nodes of the mesh's tree. */
    public int nodeCount() {
        return tree.count;
    }

    /** Depth of the mesh's tree (1 for a single leaf). */
    public int depth() {
        return tree.depth;
    }

    /** Bytes held by the packed triangles and the tree (not counting Triangle objects). */
    public long packedBytes() {
        return 8L * tri.length + 4L * tree.inner.length + 4L * tree.leaf.length + 4L * tree.order.length;
    }

    /** The triangles, in file order (made on first request when the mesh was built from arrays). */
    public List<Triangle> triangles() {
        List<Triangle> list = fileOrder;
        if (list == null) {
            Triangle[] all = new Triangle[n];
            for (int s = 0; s < n; s++) {
                int f = tree.order[s];
                double[] v = degenerate.get(f);
                int o = 0;
                if (v == null) {
                    v = tri;
                    o = 9 * s;
                }
                all[f] = new Triangle(new Vec3(v[o], v[o + 1], v[o + 2]), new Vec3(v[o + 3], v[o + 4], v[o + 5]),
                        new Vec3(v[o + 6], v[o + 7], v[o + 8]), material, name() + " triangle #" + f);
            }
            list = Collections.unmodifiableList(new ArrayList<>(List.of(all)));
            fileOrder = list;
        }
        return list;
    }
}
