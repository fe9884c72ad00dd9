package raylab.surface;

import java.util.Arrays;

/**
 * Builds a {@link BvhNodes} tree over primitives given only as boxes in a flat array: top-down,
 * binned surface area heuristic (12 bins along the longest axis of the centroids), stable
 * partition, at most 4 primitives per leaf unless they cannot be separated.
 *
 * <p>Everything is primitive arrays: one {@code int[]} order that is partitioned in place (with
 * one scratch array), the node boxes accumulated in doubles. Each level touches every primitive a
 * constant number of times, so the build is O(n log n) for a balanced split sequence. The result
 * depends only on the boxes (no threads, no hashing), so the same scene always gives the same
 * tree; it is the same tree the former object-based {@code Bvh} built.
 */
final class BvhBuilder {
    static final int BINS = 12;
    static final int MAX_LEAF = 4;
    /** Ints per node of the depth-first output: six float bounds, then two ints. */
    static final int STRIDE = 8;

    private final double[] box; // primitive i: minX, minY, minZ, maxX, maxY, maxZ at 6 i
    private final double[] cen; // centroid of primitive i at 3 i
    private final int[] order;
    private final int[] scratch;
    private int[] nodes = new int[STRIDE * 64];
    private int count;
    private int depth;
    // Reused per node: bin counts and boxes.
    private final int[] binCount = new int[BINS];
    private final double[] binBox = new double[6 * BINS];
    private final double[] left = new double[6];
    private final double[] right = new double[6];

    private BvhBuilder(double[] box, int n) {
        this.box = box;
        this.cen = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                // As BoundingBox.centroid(): (min + max)·0.5.
                cen[3 * i + k] = (box[6 * i + k] + box[6 * i + 3 + k]) * 0.5;
            }
        }
        this.order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        this.scratch = new int[n];
    }

    /** The tree over {@code n} primitives whose boxes are {@code box[6 i .. 6 i + 6)}. */
    static BvhNodes build(double[] box, int n) {
        BvhBuilder b = new BvhBuilder(box, n);
        if (n > 0) {
            b.build(0, n, 1);
        }
        return new BvhNodes(Arrays.copyOf(b.nodes, STRIDE * b.count), b.count, b.depth, b.order);
    }

    private int build(int lo, int hi, int level) {
        int node = newNode();
        depth = Math.max(depth, level);
        double nx0 = Double.POSITIVE_INFINITY, ny0 = nx0, nz0 = nx0;
        double nx1 = Double.NEGATIVE_INFINITY, ny1 = nx1, nz1 = nx1;
        double cx0 = Double.POSITIVE_INFINITY, cy0 = cx0, cz0 = cx0;
        double cx1 = Double.NEGATIVE_INFINITY, cy1 = cx1, cz1 = cx1;
        for (int i = lo; i < hi; i++) {
            int p = order[i];
            int b = 6 * p;
            nx0 = Math.min(nx0, box[b]);
            ny0 = Math.min(ny0, box[b + 1]);
            nz0 = Math.min(nz0, box[b + 2]);
            nx1 = Math.max(nx1, box[b + 3]);
            ny1 = Math.max(ny1, box[b + 4]);
            nz1 = Math.max(nz1, box[b + 5]);
            int c = 3 * p;
            cx0 = Math.min(cx0, cen[c]);
            cy0 = Math.min(cy0, cen[c + 1]);
            cz0 = Math.min(cz0, cen[c + 2]);
            cx1 = Math.max(cx1, cen[c]);
            cy1 = Math.max(cy1, cen[c + 1]);
            cz1 = Math.max(cz1, cen[c + 2]);
        }
        setBox(node, nx0, ny0, nz0, nx1, ny1, nz1);
        int n = hi - lo;
        double ex = cx1 - cx0;
        double ey = cy1 - cy0;
        double ez = cz1 - cz0;
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        double cmin = axis == 0 ? cx0 : axis == 1 ? cy0 : cz0;
        double cext = (axis == 0 ? cx1 : axis == 1 ? cy1 : cz1) - cmin;
        if (n <= MAX_LEAF || !(cext > 0)) {
            makeLeaf(node, lo, n);
            return node;
        }
        Arrays.fill(binCount, 0);
        for (int k = 0; k < BINS; k++) {
            setEmpty(binBox, 6 * k);
        }
        for (int i = lo; i < hi; i++) {
            int p = order[i];
            int bin = binOf(cen[3 * p + axis], cmin, cext);
            binCount[bin]++;
            unionInto(binBox, 6 * bin, box, 6 * p);
        }
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1;
        for (int split = 1; split < BINS; split++) {
            setEmpty(left, 0);
            setEmpty(right, 0);
            int nl = 0;
            int nr = 0;
            for (int k = 0; k < split; k++) {
                unionInto(left, 0, binBox, 6 * k);
                nl += binCount[k];
            }
            for (int k = split; k < BINS; k++) {
                unionInto(right, 0, binBox, 6 * k);
                nr += binCount[k];
            }
            if (nl == 0 || nr == 0) {
                continue;
            }
            double cost = nl * halfArea(left, 0) + nr * halfArea(right, 0);
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = split;
            }
        }
        left[0] = nx0;
        left[1] = ny0;
        left[2] = nz0;
        left[3] = nx1;
        left[4] = ny1;
        left[5] = nz1;
        double leafCost = n * halfArea(left, 0);
        if (bestSplit < 0 || (n <= 2 * MAX_LEAF && bestCost >= leafCost)) {
            makeLeaf(node, lo, n);
            return node;
        }
        // Stable partition by bin (left ones in place, right ones through the scratch array).
        int mid = lo;
        int r = 0;
        for (int i = lo; i < hi; i++) {
            int p = order[i];
            if (binOf(cen[3 * p + axis], cmin, cext) < bestSplit) {
                order[mid++] = p;
            } else {
                scratch[r++] = p;
            }
        }
        System.arraycopy(scratch, 0, order, mid, r);
        build(lo, mid, level + 1);
        int rightChild = build(mid, hi, level + 1);
        nodes[STRIDE * node + 6] = rightChild;
        nodes[STRIDE * node + 7] = -(axis + 1);
        return node;
    }

    static int binOf(double c, double cmin, double cext) {
        int bin = (int) (BINS * ((c - cmin) / cext));
        return Math.max(0, Math.min(BINS - 1, bin));
    }

    private static void setEmpty(double[] b, int k) {
        b[k] = Double.POSITIVE_INFINITY;
        b[k + 1] = Double.POSITIVE_INFINITY;
        b[k + 2] = Double.POSITIVE_INFINITY;
        b[k + 3] = Double.NEGATIVE_INFINITY;
        b[k + 4] = Double.NEGATIVE_INFINITY;
        b[k + 5] = Double.NEGATIVE_INFINITY;
    }

    private static void unionInto(double[] to, int k, double[] from, int j) {
        to[k] = Math.min(to[k], from[j]);
        to[k + 1] = Math.min(to[k + 1], from[j + 1]);
        to[k + 2] = Math.min(to[k + 2], from[j + 2]);
        to[k + 3] = Math.max(to[k + 3], from[j + 3]);
        to[k + 4] = Math.max(to[k + 4], from[j + 4]);
        to[k + 5] = Math.max(to[k + 5], from[j + 5]);
    }

    /** As BoundingBox.halfArea(): 0 for an empty box, else xy + yz + zx of the extent. */
    private static double halfArea(double[] b, int k) {
        if (b[k] > b[k + 3] || b[k + 1] > b[k + 4] || b[k + 2] > b[k + 5]) {
            return 0;
        }
        double x = b[k + 3] - b[k];
        double y = b[k + 4] - b[k + 1];
        double z = b[k + 5] - b[k + 2];
        return x * y + y * z + z * x;
    }

    private int newNode() {
        if (STRIDE * (count + 1) > nodes.length) {
            nodes = Arrays.copyOf(nodes, nodes.length * 2);
        }
        return count++;
    }

    private void makeLeaf(int node, int lo, int n) {
        nodes[STRIDE * node + 6] = lo;
        nodes[STRIDE * node + 7] = n;
    }

    private void setBox(int node, double x0, double y0, double z0, double x1, double y1, double z1) {
        int k = STRIDE * node;
        nodes[k] = Float.floatToRawIntBits(down(x0));
        nodes[k + 1] = Float.floatToRawIntBits(down(y0));
        nodes[k + 2] = Float.floatToRawIntBits(down(z0));
        nodes[k + 3] = Float.floatToRawIntBits(up(x1));
        nodes[k + 4] = Float.floatToRawIntBits(up(y1));
        nodes[k + 5] = Float.floatToRawIntBits(up(z1));
    }

    /** The largest float ≤ d (so a box stored in floats still holds everything). */
    static float down(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float ≥ d. */
    static float up(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }
}
