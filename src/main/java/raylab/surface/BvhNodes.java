package raylab.surface;

import java.util.Arrays;

import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A bounding volume hierarchy in primitive arrays, no object per node.
 *
 * <p>Inner node i occupies {@link #INNER} ints of {@link #inner} from {@code INNER·i}: the boxes of
 * its two children as six floats each (min x, y, z, max x, y, z, stored as their bits and rounded
 * outward, so a box still holds everything), then the left child's reference and
 * {@code (right reference << 2) | split axis}. A reference r ≥ 0 is inner node r; r &lt; 0 is leaf ~r, whose first primitive slot and
 * count are {@code leaf[2·~r]} and {@code leaf[2·~r + 1]}. Testing both children's boxes at the
 * parent means a missed child is never fetched nor pushed.
 *
 * <p>Traversal is depth-first and visits the left child first unless the ray goes toward −∞
 * along the split axis (the order of the tree built by {@link BvhBuilder}, so ties between equal
 * hits resolve as they always did). A pushed child carries its entry distance and is skipped when
 * popped if it lies beyond the closest hit found meanwhile. Stacks are per-thread arrays (one
 * frame per nested tree), so tracing a ray allocates nothing.
 *
 * <p>Public for the packed mesh engine (the instructor's module {@code raylab.mesh}), which traces a
 * mesh's tree with its own traversal: the arrays are the mesh's, to be read, never written.
 */
public final class BvhNodes {
    /** Ints per inner node: two boxes of six floats, the left reference, the right one with the axis. */
    public static final int INNER = 14;
    /** Relative widening of a box's exit distance, so that rounding cannot cull a hit (pbrt). */
    public static final double ROUND_UP = 1 + 2 * raylab.math.Numerics.gamma(3);

    /** The inner nodes, {@link #INNER} ints each (layout above). */
    public final int[] inner;
    /** The leaves, two ints each: first primitive slot, count. */
    public final int[] leaf;
    /** The root's reference (r ≥ 0: inner node r; r &lt; 0: leaf ~r). */
    public final int rootRef;
    /** The root's box: six float bits (min x, y, z, max x, y, z). */
    public final int[] rootBox;
    /** Nodes of the binary tree (inner + leaves), as the builder made them. */
    public final int count;
    /** Depth of the tree (1 for a single leaf). */
    public final int depth;
    /** Leaf slot → original primitive index. */
    public final int[] order;

    /**
     * Per-thread traversal stacks. A traversal may call the primitives' own intersect, which may
     * be another tree (a mesh in a scene's tree), so each traversal takes a frame above the
     * current one and gives it back when it returns. The packed mesh engine, which calls nothing
     * that traces, uses the arrays above {@link #top} without taking a frame.
     */
    public static final class Frames {
        /** Pending node references, one frame per nested tree. */
        public int[] refs = new int[256];
        /** The pending nodes' entry distances. */
        public double[] entry = new double[256];
        /** Entry distances as float bits (the packed engine's float traversal). */
        int[] bits = new int[256];
        /** Pending children of the packed engine's 4-wide traversal: entry bits << 32 | reference. */
        public long[] pending = new long[256];
        /** The ray of the packed engine's 4-wide traversal, for its leaf test (instructor-only). */
        public final double[] ray = new double[16];
        /** Four entry distances of the packed engine's Vector API traversal (instructor-only). */
        public final int[] lanes = new int[4];
        /** The first free entry of {@link #refs} and {@link #entry}: the frames below are taken. */
        public int top;
    }

    private static final ThreadLocal<Frames> FRAMES = ThreadLocal.withInitial(Frames::new);

    /** From the builder's depth-first nodes (STRIDE ints each: box, then first/right and count/−axis−1). */
    BvhNodes(int[] dfs, int count, int depth, int[] order) {
        this.count = count;
        this.depth = depth;
        this.order = order;
        int leaves = 0;
        for (int i = 0; i < count; i++) {
            if (dfs[BvhBuilder.STRIDE * i + 7] > 0) {
                leaves++;
            }
        }
        int inners = count - leaves;
        inner = new int[INNER * inners];
        leaf = new int[2 * leaves];
        int[] ref = new int[count];
        int nextInner = 0;
        int nextLeaf = 0;
        for (int i = 0; i < count; i++) {
            if (dfs[BvhBuilder.STRIDE * i + 7] > 0) {
                leaf[2 * nextLeaf] = dfs[BvhBuilder.STRIDE * i + 6];
                leaf[2 * nextLeaf + 1] = dfs[BvhBuilder.STRIDE * i + 7];
                ref[i] = ~nextLeaf++;
            } else {
                ref[i] = nextInner++;
            }
        }
        for (int i = 0; i < count; i++) {
            int k = BvhBuilder.STRIDE * i;
            if (dfs[k + 7] <= 0) {
                int o = INNER * ref[i];
                int left = i + 1;
                int right = dfs[k + 6];
                System.arraycopy(dfs, BvhBuilder.STRIDE * left, inner, o, 6);
                System.arraycopy(dfs, BvhBuilder.STRIDE * right, inner, o + 6, 6);
                inner[o + 12] = ref[left];
                inner[o + 13] = ref[right] << 2 | (-dfs[k + 7] - 1);
            }
        }
        rootRef = count == 0 ? 0 : ref[0];
        rootBox = count == 0 ? new int[6] : Arrays.copyOf(dfs, 6);
    }

    /** Number of inner nodes. */
    public int innerCount() {
        return inner.length / INNER;
    }

    /** This thread's traversal stacks. */
    public static Frames frames() {
        return FRAMES.get();
    }

    /** Makes room for {@code need} entries; the caller's arrays keep their frames if replaced. */
    public static void ensure(Frames f, int need) {
        if (f.refs.length < need) {
            int cap = Math.max(need, 2 * f.refs.length);
            f.refs = Arrays.copyOf(f.refs, cap);
            f.entry = Arrays.copyOf(f.entry, cap);
            f.bits = Arrays.copyOf(f.bits, cap);
            f.pending = Arrays.copyOf(f.pending, cap);
        }
    }

    /**
     * Entry distance of the ray p + t·d (inverse direction components ix, iy, iz) into the box
     * of six float bits at {@code box[k ..]} for t in [t0, t1], or +∞ if it misses. nx, ny, nz
     * are 0 or 3: the offset of the near face along each axis (3 when the direction component is
     * negative). Slabs; a 0·∞ NaN (origin on a slab plane, direction parallel to it) is ignored,
     * counting as inside.
     */
    public static double entry(int[] box, int k, double px, double py, double pz, double ix, double iy,
            double iz, int nx, int ny, int nz, double t0, double t1) {
        return entry(box, k, px, py, pz, ix, iy, iz, ix * ROUND_UP, iy * ROUND_UP, iz * ROUND_UP, nx, ny, nz, t0, t1);
    }

    /**
     * As above with the exit side's inverse direction already widened: ux = ix·(1 + 2γ3), and so
     * on. (f − p)·ux rounds four times (1/d, the difference, the widening, the product), within
     * γ4 &lt; 2γ3 of the exact exit distance, so the widened exit still bounds it from above.
     */
    public static double entry(int[] box, int k, double px, double py, double pz, double ix, double iy,
            double iz, double ux, double uy, double uz, int nx, int ny, int nz, double t0, double t1) {
        double a = (Float.intBitsToFloat(box[k + nx]) - px) * ix;
        double b = (Float.intBitsToFloat(box[k + 3 - nx]) - px) * ux;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        a = (Float.intBitsToFloat(box[k + 1 + ny]) - py) * iy;
        b = (Float.intBitsToFloat(box[k + 4 - ny]) - py) * uy;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        a = (Float.intBitsToFloat(box[k + 2 + nz]) - pz) * iz;
        b = (Float.intBitsToFloat(box[k + 5 - nz]) - pz) * uz;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    /**
     * Closest hit (or any hit) among {@code prims}, given in leaf-slot order: the leaf test asks
     * each surface's own {@code intersect}. Counts the primitive tests in {@code rec.tests}.
     */
    boolean traverse(IntersectionRecord rec, Ray ray, Surface[] prims, boolean anyHit) {
        if (count == 0) {
            return false;
        }
        Frames f = frames();
        int base = f.top;
        ensure(f, base + depth + 1);
        f.top = base + depth + 1;
        try {
            return traverse(rec, ray, prims, anyHit, f.refs, f.entry, base);
        } finally {
            f.top = base;
        }
    }

    private boolean traverse(IntersectionRecord rec, Ray ray, Surface[] prims, boolean anyHit, int[] refs,
            double[] entries, int base) {
        final double px = ray.p.x, py = ray.p.y, pz = ray.p.z;
        final double ix = 1.0 / ray.d.x, iy = 1.0 / ray.d.y, iz = 1.0 / ray.d.z;
        final int nx = ix < 0 ? 3 : 0, ny = iy < 0 ? 3 : 0, nz = iz < 0 ? 3 : 0;
        final double tMin = ray.tMin, tMax = ray.tMax;
        final int[] inner = this.inner;
        if (entry(rootBox, 0, px, py, pz, ix, iy, iz, nx, ny, nz, tMin, Math.min(tMax, rec.t)) == Double.POSITIVE_INFINITY) {
            return false;
        }
        int top = base;
        int ref = rootRef;
        boolean hit = false;
        while (true) {
            if (ref < 0) {
                int l = 2 * ~ref;
                int end = leaf[l] + leaf[l + 1];
                for (int i = leaf[l]; i < end; i++) {
                    rec.tests++;
                    if (prims[i].intersect(rec, ray)) {
                        hit = true;
                        if (anyHit) {
                            return true;
                        }
                    }
                }
            } else {
                int k = INNER * ref;
                double t1 = Math.min(tMax, rec.t);
                double tl = entry(inner, k, px, py, pz, ix, iy, iz, nx, ny, nz, tMin, t1);
                double tr = entry(inner, k + 6, px, py, pz, ix, iy, iz, nx, ny, nz, tMin, t1);
                int packed = inner[k + 13];
                int axis = packed & 3;
                boolean rightFirst = (axis == 0 ? nx : axis == 1 ? ny : nz) != 0;
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
            // Pop the next pending child that can still hold a closer hit.
            while (true) {
                if (top == base) {
                    return hit;
                }
                top--;
                if (entries[top] <= Math.min(tMax, rec.t)) {
                    ref = refs[top];
                    break;
                }
            }
        }
    }
}
