package raylab.surface;

import java.util.Arrays;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;

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
 *
 * <p>Large inputs ({@link #PARALLEL_MIN} primitives and more) build the two subtrees of every node
 * above that size in parallel, each into its own node array, and then append them in depth-first
 * order: the result is identical to the sequential build, node for node.
 *
 * <p>Public for {@link #up} only, which the packed mesh engine ({@code raylab.mesh}) rounds with.
 */
public final class BvhBuilder {
    static final int BINS = 12;
    static final int MAX_LEAF = 4;
    /** Ints per node of the depth-first output: six float bounds, then two ints. */
    static final int STRIDE = 8;
    /** Subtrees of at least this many primitives are built in parallel. */
    static final int PARALLEL_MIN = 1 << 15;

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
    private final double[] suffixBox = new double[6 * BINS];
    private final int[] suffixCount = new int[BINS];
    /** Written by {@link #bounds}: the node's box, then its centroids' box. */
    private final double[] nodeBounds = new double[12];
    /** Written by {@link #bestSplit}. */
    private double bestCost;

    private BvhBuilder(double[] box, double[] cen, int[] order, int[] scratch) {
        this.box = box;
        this.cen = cen;
        this.order = order;
        this.scratch = scratch;
    }

    /** The tree over {@code n} primitives whose boxes are {@code box[6 i .. 6 i + 6)}. */
    static BvhNodes build(double[] box, int n) {
        return build(box, n, Runtime.getRuntime().availableProcessors());
    }

    /** As {@link #build(double[], int)}, with at most {@code threads} threads. */
    static BvhNodes build(double[] box, int n, int threads) {
        double[] cen = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                // As BoundingBox.centroid(): (min + max)·0.5.
                cen[3 * i + k] = (box[6 * i + k] + box[6 * i + 3 + k]) * 0.5;
            }
        }
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        BvhBuilder b = new BvhBuilder(box, cen, order, new int[n]);
        if (n >= 2 * PARALLEL_MIN && threads > 1) {
            ForkJoinPool pool = new ForkJoinPool(threads);
            try {
                pool.invoke(new Task(b, 0, n, 1, true));
            } finally {
                pool.shutdown();
            }
        } else if (n > 0) {
            b.build(0, n, 1, false);
        }
        return new BvhNodes(Arrays.copyOf(b.nodes, STRIDE * b.count), b.count, b.depth, order);
    }

    /** Builds one subtree into its builder. */
    private static final class Task extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient BvhBuilder b;
        private final int lo;
        private final int hi;
        private final int level;
        private final boolean parallel;

        Task(BvhBuilder b, int lo, int hi, int level, boolean parallel) {
            this.b = b;
            this.lo = lo;
            this.hi = hi;
            this.level = level;
            this.parallel = parallel;
        }

        @Override
        protected void compute() {
            b.build(lo, hi, level, parallel);
        }
    }

    private int build(int lo, int hi, int level, boolean parallel) {
        int node = newNode();
        depth = Math.max(depth, level);
        // Small methods, one pass each, so the JIT compiles them early in a large build.
        bounds(lo, hi);
        double[] nb = nodeBounds;
        setBox(node, nb[0], nb[1], nb[2], nb[3], nb[4], nb[5]);
        int n = hi - lo;
        double ex = nb[9] - nb[6];
        double ey = nb[10] - nb[7];
        double ez = nb[11] - nb[8];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        double cmin = nb[6 + axis];
        double cext = nb[9 + axis] - cmin;
        if (n <= MAX_LEAF || !(cext > 0)) {
            makeLeaf(node, lo, n);
            return node;
        }
        binPrimitives(lo, hi, axis, cmin, cext);
        int bestSplit = bestSplit();
        double leafCost = n * halfArea(nb, 0);
        if (bestSplit < 0 || (n <= 2 * MAX_LEAF && bestCost >= leafCost)) {
            makeLeaf(node, lo, n);
            return node;
        }
        int mid = partition(lo, hi, axis, cmin, cext, bestSplit);
        int rightChild;
        if (parallel && n >= PARALLEL_MIN) {
            // Disjoint ranges of order and scratch; separate node arrays, appended in order.
            BvhBuilder left = new BvhBuilder(box, cen, order, scratch);
            BvhBuilder right = new BvhBuilder(box, cen, order, scratch);
            ForkJoinTask.invokeAll(new Task(left, lo, mid, level + 1, true), new Task(right, mid, hi, level + 1, true));
            append(left);
            rightChild = count;
            append(right);
        } else {
            build(lo, mid, level + 1, parallel);
            rightChild = build(mid, hi, level + 1, parallel);
        }
        nodes[STRIDE * node + 6] = rightChild;
        nodes[STRIDE * node + 7] = -(axis + 1);
        return node;
    }

    /**
     * The bounds of primitives lo..hi into {@link #nodeBounds}: their box (min x, y, z, max x, y,
     * z), then the box of their centroids.
     */
    private void bounds(int lo, int hi) {
        double nx0 = Double.POSITIVE_INFINITY, ny0 = nx0, nz0 = nx0;
        double nx1 = Double.NEGATIVE_INFINITY, ny1 = nx1, nz1 = nx1;
        double cx0 = Double.POSITIVE_INFINITY, cy0 = cx0, cz0 = cx0;
        double cx1 = Double.NEGATIVE_INFINITY, cy1 = cx1, cz1 = cx1;
        for (int i = lo; i < hi; i++) {
            int p = order[i];
            int b = 6 * p;
            // Plain comparisons: no NaN here, and the sign of a zero bound changes no decision.
            double v = box[b];
            nx0 = v < nx0 ? v : nx0;
            v = box[b + 1];
            ny0 = v < ny0 ? v : ny0;
            v = box[b + 2];
            nz0 = v < nz0 ? v : nz0;
            v = box[b + 3];
            nx1 = v > nx1 ? v : nx1;
            v = box[b + 4];
            ny1 = v > ny1 ? v : ny1;
            v = box[b + 5];
            nz1 = v > nz1 ? v : nz1;
            int c = 3 * p;
            v = cen[c];
            cx0 = v < cx0 ? v : cx0;
            cx1 = v > cx1 ? v : cx1;
            v = cen[c + 1];
            cy0 = v < cy0 ? v : cy0;
            cy1 = v > cy1 ? v : cy1;
            v = cen[c + 2];
            cz0 = v < cz0 ? v : cz0;
            cz1 = v > cz1 ? v : cz1;
        }
        double[] nb = nodeBounds;
        nb[0] = nx0;
        nb[1] = ny0;
        nb[2] = nz0;
        nb[3] = nx1;
        nb[4] = ny1;
        nb[5] = nz1;
        nb[6] = cx0;
        nb[7] = cy0;
        nb[8] = cz0;
        nb[9] = cx1;
        nb[10] = cy1;
        nb[11] = cz1;
    }

    /** Counts primitives lo..hi per bin along the axis and grows each bin's box. */
    private void binPrimitives(int lo, int hi, int axis, double cmin, double cext) {
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
    }

    /**
     * The split (1 to BINS − 1: bins below it go left) of least surface area cost, the first of
     * equal ones, or −1 if every split leaves a side empty; its cost goes to {@link #bestCost}.
     * Every split's two boxes come from one sweep from each end (a union of boxes is exact, so
     * they are the boxes a union from scratch gives).
     */
    private int bestSplit() {
        setEmpty(right, 0);
        int nr = 0;
        for (int k = BINS - 1; k >= 1; k--) {
            unionInto(right, 0, binBox, 6 * k);
            nr += binCount[k];
            System.arraycopy(right, 0, suffixBox, 6 * k, 6);
            suffixCount[k] = nr;
        }
        setEmpty(left, 0);
        int nl = 0;
        bestCost = Double.POSITIVE_INFINITY;
        int best = -1;
        for (int split = 1; split < BINS; split++) {
            unionInto(left, 0, binBox, 6 * (split - 1));
            nl += binCount[split - 1];
            nr = suffixCount[split];
            if (nl == 0 || nr == 0) {
                continue;
            }
            double cost = nl * halfArea(left, 0) + nr * halfArea(suffixBox, 6 * split);
            if (cost < bestCost) {
                bestCost = cost;
                best = split;
            }
        }
        return best;
    }

    /** Stable partition of lo..hi by bin (left ones in place, right ones through the scratch array); returns the first right one. */
    private int partition(int lo, int hi, int axis, double cmin, double cext, int split) {
        int mid = lo;
        int r = 0;
        for (int i = lo; i < hi; i++) {
            int p = order[i];
            if (binOf(cen[3 * p + axis], cmin, cext) < split) {
                order[mid++] = p;
            } else {
                scratch[lo + r++] = p;
            }
        }
        System.arraycopy(scratch, lo, order, mid, r);
        return mid;
    }

    /** Appends a subtree built by another builder, shifting its node references. */
    private void append(BvhBuilder sub) {
        int base = count;
        while (STRIDE * (count + sub.count) > nodes.length) {
            nodes = Arrays.copyOf(nodes, nodes.length * 2);
        }
        System.arraycopy(sub.nodes, 0, nodes, STRIDE * base, STRIDE * sub.count);
        for (int i = base; i < base + sub.count; i++) {
            if (nodes[STRIDE * i + 7] <= 0) {
                nodes[STRIDE * i + 6] += base;
            }
        }
        count += sub.count;
        depth = Math.max(depth, sub.depth);
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
        for (int i = 0; i < 3; i++) {
            double lo = from[j + i];
            double hi = from[j + 3 + i];
            if (lo < to[k + i]) {
                to[k + i] = lo;
            }
            if (hi > to[k + 3 + i]) {
                to[k + 3 + i] = hi;
            }
        }
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
    public static float up(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }
}
