package raylab.mesh;

import raylab.surface.BvhBuilder;
import raylab.surface.BvhNodes;

/**
 * The packed engine's 4-wide tree (instructor-only, as
 * {@code PackedTriangles}): the binary SAH tree of {@link BvhNodes} collapsed so that each node
 * holds up to four children, its two children's children where those are inner nodes, else the
 * child itself. Traversed by {@link PackedOctants}, one copy per ray octant.
 *
 * <p>Node i is 32 floats of {@link #node} from 32 i: the children's boxes as structure of arrays
 * (min x of children 0–3, max x of 0–3, min y, max y, min z, max z: 24 floats), the four child
 * references as float bits (r ≥ 0: node r; r &lt; 0: leaf ~r of {@link BvhNodes#leaf}), then the
 * visit order for each octant as one byte (octants 0–3 in float 28, 4–7 in float 29: four 2-bit
 * child numbers, the first visited in the low bits). An empty child slot has the box
 * [+∞, −∞], which no ray enters. Children 0 and 1 come from the binary node's left child, 2 and 3
 * from its right one; the visit order is the binary tree's (left first unless the ray goes toward
 * −∞ along the split axis, at both levels), so the 4-wide traversal keeps the same hit as the
 * binary ones, ties included.
 *
 * <p>Boxes are the builder's float boxes (rounded outward from the doubles), snapped outward to 0
 * or ±2⁻⁷² when smaller than that in magnitude ({@link PackedTriangles#grid}).
 */
final class PackedWide {
    /** Floats per node. */
    static final int NODE = 32;
    /**
     * Widening of the box test, in units in the last place: a child is entered when
     * entry − K ≤ exit as float bits. A computed slab distance (o' − b)·m is within (1 + 1.01u)³ of
     * (o' − b)·(−1/d) (u = 2⁻²⁴: the difference, −1/d rounded to double then to float, the product),
     * and o' lies on the safe side of o, so an entry is at most t·(1 + 3.04u) and an exit at least
     * t·(1 − 3.04u) where t ≥ 0; K ulps add at least a factor 1 + K·u to a positive float, more than
     * the 1 + 6.1u between them (or, in the subnormal range, where a product's rounding is absolute,
     * more than its 2⁻¹⁵⁰ twice).
     */
    static final int K = 16;

    final float[] node;
    /** The root: node 0, or the binary tree's single leaf (a negative reference). */
    final int root;
    /** Whether every box lies within ±{@link PackedTriangles#HUGE} (else the double traversal). */
    final boolean inRange;
    private int next;
    private final int[] inner;

    PackedWide(BvhNodes tree) {
        inner = tree.inner;
        int inners = tree.innerCount();
        float[] nodes = new float[NODE * Math.max(1, inners)];
        boolean range = true;
        for (int i = 0; i < 12 * inners; i++) {
            int k = BvhNodes.INNER * (i / 12) + i % 12;
            range &= Math.abs(Float.intBitsToFloat(inner[k])) <= PackedTriangles.HUGE;
        }
        inRange = range;
        if (tree.count == 0 || tree.rootRef < 0) {
            root = tree.count == 0 ? 0 : tree.rootRef;
            node = new float[0];
        } else {
            root = 0;
            make(tree.rootRef, nodes);
            node = java.util.Arrays.copyOf(nodes, NODE * next);
        }
    }

    /**
     * The 4-wide node of binary inner node i (depth first, so the root is node 0); its index. Its
     * children: i's two children, then, while fewer than four, the inner one of largest surface
     * area replaced by its own two children. The visit order for an octant is the binary tree's
     * among them (left first unless the ray goes toward −∞ along the split axis).
     */
    private int make(int i, float[] out) {
        int w = next++;
        int o = NODE * w;
        // Frontier: binary references and the offsets of their boxes in inner.
        int[] refs = new int[4];
        int[] boxes = new int[4];
        int count = 2;
        int k = BvhNodes.INNER * i;
        refs[0] = inner[k + 12];
        boxes[0] = k;
        refs[1] = inner[k + 13] >> 2;
        boxes[1] = k + 6;
        int[] opened = new int[3];
        opened[0] = i;
        int openedCount = 1;
        while (count < 4) {
            int pick = -1;
            double largest = -1;
            for (int c = 0; c < count; c++) {
                if (refs[c] >= 0 && area(boxes[c]) > largest) {
                    largest = area(boxes[c]);
                    pick = c;
                }
            }
            if (pick < 0) {
                break;
            }
            int j = refs[pick];
            int kj = BvhNodes.INNER * j;
            opened[openedCount++] = j;
            refs[pick] = inner[kj + 12];
            boxes[pick] = kj;
            refs[count] = inner[kj + 13] >> 2;
            boxes[count] = kj + 6;
            count++;
        }
        for (int c = 0; c < 4; c++) {
            if (c < count) {
                box(out, o, c, boxes[c]);
            } else {
                for (int a = 0; a < 3; a++) {
                    out[o + 8 * a + c] = Float.POSITIVE_INFINITY;
                    out[o + 8 * a + 4 + c] = Float.NEGATIVE_INFINITY;
                }
            }
        }
        int lo = 0, hi = 0;
        for (int oct = 0; oct < 8; oct++) {
            int[] order = new int[4];
            int filled = visit(i, oct, refs, count, opened, openedCount, order, 0);
            for (int c = 0; c < 4; c++) {
                if (!contains(order, filled, c)) {
                    order[filled++] = c; // empty slots last
                }
            }
            int bits = 0;
            for (int j = 0; j < 4; j++) {
                bits |= order[j] << 2 * j;
            }
            if (oct < 4) {
                lo |= bits << 8 * oct;
            } else {
                hi |= bits << 8 * (oct - 4);
            }
        }
        out[o + 28] = Float.intBitsToFloat(lo);
        out[o + 29] = Float.intBitsToFloat(hi);
        out[o + 30] = Float.intBitsToFloat(count);
        for (int c = 0; c < 4; c++) {
            // An empty slot keeps reference 0: its box is never entered.
            int r = c < count && refs[c] >= 0 ? make(refs[c], out) : c < count ? refs[c] : 0;
            out[o + 24 + c] = Float.intBitsToFloat(r);
        }
        return w;
    }

    /** Appends the slots under binary node j in the binary tree's visit order for the octant. */
    private int visit(int j, int oct, int[] refs, int count, int[] opened, int openedCount, int[] order, int n) {
        int k = BvhNodes.INNER * j;
        boolean rightFirst = (oct >> (inner[k + 13] & 3) & 1) != 0;
        for (int side = 0; side < 2; side++) {
            int child = (side == 0) != rightFirst ? inner[k + 12] : inner[k + 13] >> 2;
            if (child >= 0 && contains(opened, openedCount, child)) {
                n = visit(child, oct, refs, count, opened, openedCount, order, n);
            } else {
                for (int c = 0; c < count; c++) {
                    if (refs[c] == child) {
                        order[n++] = c;
                    }
                }
            }
        }
        return n;
    }

    private static boolean contains(int[] a, int n, int v) {
        for (int i = 0; i < n; i++) {
            if (a[i] == v) {
                return true;
            }
        }
        return false;
    }

    /** Half the surface area of the box of six float bits at inner[k ..). */
    private double area(int k) {
        double x = (double) Float.intBitsToFloat(inner[k + 3]) - Float.intBitsToFloat(inner[k]);
        double y = (double) Float.intBitsToFloat(inner[k + 4]) - Float.intBitsToFloat(inner[k + 1]);
        double z = (double) Float.intBitsToFloat(inner[k + 5]) - Float.intBitsToFloat(inner[k + 2]);
        return x * y + y * z + z * x;
    }

    /** Child slot s of the node at out[o ..) gets the box of six float bits at inner[k ..). */
    private void box(float[] out, int o, int s, int k) {
        for (int a = 0; a < 3; a++) {
            out[o + 8 * a + s] = PackedTriangles.grid(Float.intBitsToFloat(inner[k + a]), false);
            out[o + 8 * a + 4 + s] = PackedTriangles.grid(Float.intBitsToFloat(inner[k + 3 + a]), true);
        }
    }

    /** The float ≥ t (t ≥ 0) as raw bits (+∞ for +∞): the far end of the search. */
    static int exitBits(double t) {
        return Float.floatToRawIntBits(BvhBuilder.up(t));
    }

    /**
     * Slots of the per-thread ray array of the leaf test ({@link PackedOctants}): origin, tMin, tMax,
     * the closest hit so far, the shear and the origin in ray space (as
     * {@link raylab.surface.Triangle#intersect}), the count of triangle tests.
     */
    static final int PX = 0, PY = 1, PZ = 2, TMIN = 3, TMAX = 4, BEST = 5, SHX = 6, SHY = 7, SHZ = 8, PKX = 9,
            PKY = 10, PKZ = 11, TESTS = 12, RAY = 13;

    /**
     * A float strictly below q (an origin coordinate, |q| ≤ 2⁶⁰): q lowered by 2⁻²²·|q| + 2⁻¹⁴⁰ in
     * double, more than the double's rounding and the rounding to float (half a float ulp: at most
     * 2⁻²⁴·|q|, or 2⁻¹⁵⁰ below the normal range) together. Branch-free, so rays whose origins differ
     * (shadow rays) pay no mispredicted branch.
     */
    static float below(double q) {
        return (float) (q - Math.abs(q) * 0x1p-22 - 0x1p-140);
    }

    /** A float strictly above q (as {@link #below}). */
    static float above(double q) {
        return (float) (q + Math.abs(q) * 0x1p-22 + 0x1p-140);
    }

    /** Bytes held. */
    long bytes() {
        return 4L * node.length;
    }
}
