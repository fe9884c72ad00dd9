package raylab.surface;

import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A bounding volume hierarchy as one {@code int[]}: node i occupies {@link #STRIDE} ints from
 * {@code STRIDE·i}: its box as six floats (min x, y, z, max x, y, z, stored as their bits and
 * rounded outward, so the box still holds everything) and two ints: for a leaf the first primitive
 * slot and the count (&gt; 0); for an inner node the right child's index and −(split axis + 1).
 * The left child of an inner node is the next node (depth-first order). No object per node.
 *
 * <p>{@link #order} maps a leaf slot to the primitive's original index. Traversal visits the
 * nearer child first (by the sign of the ray direction along the split axis) and keeps its stack
 * in a per-thread array (one frame per nested tree), so tracing a ray allocates nothing.
 */
final class BvhNodes {
    /** Ints per node: six float bounds, then two ints. */
    static final int STRIDE = 8;
    /** Relative widening of a box's exit distance, so that rounding cannot cull a hit (pbrt). */
    static final double ROUND_UP = 1 + 2 * raylab.math.Numerics.gamma(3);

    final int[] nodes;
    final int count;
    final int depth;
    /** Leaf slot → original primitive index. */
    final int[] order;

    /**
     * Per-thread traversal stacks. A traversal calls the primitives' own intersect, which may be
     * another tree (a mesh in a scene's tree), so each traversal takes a frame above the current
     * one and gives it back when it returns.
     */
    private static final class Frames {
        int[] stack = new int[256];
        int top;
    }

    private static final ThreadLocal<Frames> FRAMES = ThreadLocal.withInitial(Frames::new);

    BvhNodes(int[] nodes, int count, int depth, int[] order) {
        this.nodes = nodes;
        this.count = count;
        this.depth = depth;
        this.order = order;
    }

    /**
     * Whether the ray p + t·d (with inverse direction components ix, iy, iz) meets the box of the
     * node at int offset k for some t in [t0, t1]. nx, ny, nz are 0 or 3: the offset of the
     * near face along each axis (3 when the direction component is negative). Slabs; a 0·∞ NaN
     * (origin on a slab plane, direction parallel to it) is ignored, counting as inside.
     */
    static boolean hits(int[] nodes, int k, double px, double py, double pz, double ix, double iy,
            double iz, int nx, int ny, int nz, double t0, double t1) {
        double a = (Float.intBitsToFloat(nodes[k + nx]) - px) * ix;
        double b = (Float.intBitsToFloat(nodes[k + 3 - nx]) - px) * ix * ROUND_UP;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        a = (Float.intBitsToFloat(nodes[k + 1 + ny]) - py) * iy;
        b = (Float.intBitsToFloat(nodes[k + 4 - ny]) - py) * iy * ROUND_UP;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        a = (Float.intBitsToFloat(nodes[k + 2 + nz]) - pz) * iz;
        b = (Float.intBitsToFloat(nodes[k + 5 - nz]) - pz) * iz * ROUND_UP;
        t0 = a > t0 ? a : t0;
        t1 = b < t1 ? b : t1;
        return t0 <= t1;
    }

    /**
     * Closest hit (or any hit) among {@code prims}, given in leaf-slot order: the leaf test asks
     * each surface's own {@code intersect}. Counts the primitive tests in {@code rec.tests}.
     */
    boolean traverse(IntersectionRecord rec, Ray ray, Surface[] prims, boolean anyHit) {
        if (count == 0) {
            return false;
        }
        Frames f = FRAMES.get();
        int base = f.top;
        int need = base + depth + 1;
        if (f.stack.length < need) {
            // The caller keeps its reference to the old array, whose frames stay intact.
            f.stack = java.util.Arrays.copyOf(f.stack, Math.max(need, 2 * f.stack.length));
        }
        int[] stack = f.stack;
        f.top = need;
        try {
            return traverse(rec, ray, prims, anyHit, stack, base);
        } finally {
            f.top = base;
        }
    }

    private boolean traverse(IntersectionRecord rec, Ray ray, Surface[] prims, boolean anyHit, int[] stack,
            int base) {
        double px = ray.p.x;
        double py = ray.p.y;
        double pz = ray.p.z;
        double ix = 1.0 / ray.d.x;
        double iy = 1.0 / ray.d.y;
        double iz = 1.0 / ray.d.z;
        int nx = ix < 0 ? 3 : 0;
        int ny = iy < 0 ? 3 : 0;
        int nz = iz < 0 ? 3 : 0;
        int[] nodes = this.nodes;
        int top = base;
        int node = 0;
        boolean hit = false;
        while (true) {
            int k = STRIDE * node;
            if (hits(nodes, k, px, py, pz, ix, iy, iz, nx, ny, nz, ray.tMin, Math.min(ray.tMax, rec.t))) {
                int tag = nodes[k + 7];
                if (tag > 0) {
                    int end = nodes[k + 6] + tag;
                    for (int i = nodes[k + 6]; i < end; i++) {
                        rec.tests++;
                        if (prims[i].intersect(rec, ray)) {
                            hit = true;
                            if (anyHit) {
                                return true;
                            }
                        }
                    }
                } else {
                    int axis = -tag - 1;
                    boolean negative = (axis == 0 ? nx : axis == 1 ? ny : nz) != 0;
                    if (negative) {
                        stack[top++] = node + 1;
                        node = nodes[k + 6];
                    } else {
                        stack[top++] = nodes[k + 6];
                        node = node + 1;
                    }
                    continue;
                }
            }
            if (top == base) {
                return hit;
            }
            node = stack[--top];
        }
    }
}
