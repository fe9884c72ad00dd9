package raylab.surface;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A bounding volume hierarchy: the same closest hit as {@link Group}, found by skipping every
 * subtree whose bounding box the ray misses or reaches only beyond the closest hit so far.
 *
 * <p>Built top-down with the surface area heuristic over 12 bins per axis; nodes are stored in
 * flat arrays, and traversal visits the nearer child first. Building is deterministic, so the
 * same scene always gives the same tree (and the same image).
 */
public final class Bvh extends Surface {
    private static final int BINS = 12;
    private static final int MAX_LEAF = 4;

    private final Surface[] prims;
    // Node i: box [minX..maxZ], and either a leaf (count > 0: prims[first .. first+count))
    // or an inner node (count == 0: children i + 1 and second[i]).
    private double[] bounds = new double[6 * 64];
    private int[] first = new int[64];
    private int[] count = new int[64];
    private int[] second = new int[64];
    private int axisOf[] = new int[64];
    private int nodes;
    private int depth;
    private final BoundingBox box;

    public Bvh(List<? extends Surface> surfaces, String name) {
        super(null, name);
        this.prims = surfaces.toArray(new Surface[0]);
        int n = prims.length;
        BoundingBox[] boxes = new BoundingBox[n];
        Vec3[] centroids = new Vec3[n];
        for (int i = 0; i < n; i++) {
            boxes[i] = prims[i].boundingBox();
            centroids[i] = boxes[i].centroid();
        }
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        build(order, boxes, centroids, 0, n, 1);
        Surface[] sorted = new Surface[n];
        for (int i = 0; i < n; i++) {
            sorted[i] = prims[order[i]];
        }
        System.arraycopy(sorted, 0, prims, 0, n);
        box = n == 0 ? BoundingBox.EMPTY : nodeBox(0);
    }

    private int build(Integer[] order, BoundingBox[] boxes, Vec3[] centroids, int lo, int hi, int level) {
        int node = newNode();
        depth = Math.max(depth, level);
        BoundingBox nb = BoundingBox.EMPTY;
        BoundingBox cb = BoundingBox.EMPTY;
        for (int i = lo; i < hi; i++) {
            nb = nb.union(boxes[order[i]]);
            cb = cb.union(centroids[order[i]]);
        }
        setBox(node, nb);
        int n = hi - lo;
        int axis = cb.longestAxis();
        double cmin = cb.min.get(axis);
        double cext = cb.max.get(axis) - cmin;
        if (n <= MAX_LEAF || !(cext > 0)) {
            makeLeaf(node, lo, n);
            return node;
        }
        // Surface area heuristic over BINS buckets of centroids along the longest axis.
        int[] binCount = new int[BINS];
        BoundingBox[] binBox = new BoundingBox[BINS];
        Arrays.fill(binBox, BoundingBox.EMPTY);
        for (int i = lo; i < hi; i++) {
            int bin = binOf(centroids[order[i]].get(axis), cmin, cext);
            binCount[bin]++;
            binBox[bin] = binBox[bin].union(boxes[order[i]]);
        }
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1;
        for (int split = 1; split < BINS; split++) {
            BoundingBox left = BoundingBox.EMPTY;
            BoundingBox right = BoundingBox.EMPTY;
            int nl = 0;
            int nr = 0;
            for (int k = 0; k < split; k++) {
                left = left.union(binBox[k]);
                nl += binCount[k];
            }
            for (int k = split; k < BINS; k++) {
                right = right.union(binBox[k]);
                nr += binCount[k];
            }
            if (nl == 0 || nr == 0) {
                continue;
            }
            double cost = nl * left.halfArea() + nr * right.halfArea();
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = split;
            }
        }
        double leafCost = n * nb.halfArea();
        if (bestSplit < 0 || (n <= 2 * MAX_LEAF && bestCost >= leafCost)) {
            makeLeaf(node, lo, n);
            return node;
        }
        // Stable partition by bin keeps the build deterministic.
        List<Integer> left = new ArrayList<>();
        List<Integer> right = new ArrayList<>();
        for (int i = lo; i < hi; i++) {
            int bin = binOf(centroids[order[i]].get(axis), cmin, cext);
            (bin < bestSplit ? left : right).add(order[i]);
        }
        int mid = lo;
        for (Integer k : left) {
            order[mid++] = k;
        }
        int j = mid;
        for (Integer k : right) {
            order[j++] = k;
        }
        count[node] = 0;
        axisOf[node] = axis;
        build(order, boxes, centroids, lo, mid, level + 1);
        // Build first, then store: build may grow (reallocate) the arrays.
        int rightChild = build(order, boxes, centroids, mid, hi, level + 1);
        second[node] = rightChild;
        return node;
    }

    private static int binOf(double c, double cmin, double cext) {
        int bin = (int) (BINS * ((c - cmin) / cext));
        return Math.max(0, Math.min(BINS - 1, bin));
    }

    private int newNode() {
        if (nodes == first.length) {
            int cap = nodes * 2;
            bounds = Arrays.copyOf(bounds, 6 * cap);
            first = Arrays.copyOf(first, cap);
            count = Arrays.copyOf(count, cap);
            second = Arrays.copyOf(second, cap);
            axisOf = Arrays.copyOf(axisOf, cap);
        }
        return nodes++;
    }

    private void makeLeaf(int node, int lo, int n) {
        first[node] = lo;
        count[node] = n;
    }

    private void setBox(int node, BoundingBox b) {
        int k = 6 * node;
        bounds[k] = b.min.x;
        bounds[k + 1] = b.min.y;
        bounds[k + 2] = b.min.z;
        bounds[k + 3] = b.max.x;
        bounds[k + 4] = b.max.y;
        bounds[k + 5] = b.max.z;
    }

    private BoundingBox nodeBox(int node) {
        int k = 6 * node;
        return new BoundingBox(new Vec3(bounds[k], bounds[k + 1], bounds[k + 2]),
                new Vec3(bounds[k + 3], bounds[k + 4], bounds[k + 5]));
    }

    /** Whether the ray meets node's box for some t in [ray.tMin, tMax]; slabs, conservatively. */
    private boolean hitsNode(int node, Ray ray, double ix, double iy, double iz, double tMax) {
        int k = 6 * node;
        double t0 = ray.tMin;
        double t1 = tMax;
        double a = (bounds[k] - ray.p.x) * ix;
        double b = (bounds[k + 3] - ray.p.x) * ix;
        t0 = Math.max(t0, nanToLow(Math.min(a, b)));
        t1 = Math.min(t1, nanToHigh(Math.max(a, b)) * ROUND_UP);
        a = (bounds[k + 1] - ray.p.y) * iy;
        b = (bounds[k + 4] - ray.p.y) * iy;
        t0 = Math.max(t0, nanToLow(Math.min(a, b)));
        t1 = Math.min(t1, nanToHigh(Math.max(a, b)) * ROUND_UP);
        a = (bounds[k + 2] - ray.p.z) * iz;
        b = (bounds[k + 5] - ray.p.z) * iz;
        t0 = Math.max(t0, nanToLow(Math.min(a, b)));
        t1 = Math.min(t1, nanToHigh(Math.max(a, b)) * ROUND_UP);
        return t0 <= t1;
    }

    // 0·∞ (origin on a slab plane, direction parallel to it) gives NaN: count it as inside.
    private static double nanToLow(double v) {
        return v != v ? Double.NEGATIVE_INFINITY : v;
    }

    private static double nanToHigh(double v) {
        return v != v ? Double.POSITIVE_INFINITY : v;
    }

    private static final double ROUND_UP = 1 + 2 * raylab.math.Numerics.gamma(3);

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        return traverse(outRecord, ray, false);
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        scratch.reset();
        return traverse(scratch, ray, true);
    }

    private boolean traverse(IntersectionRecord rec, Ray ray, boolean anyHit) {
        if (prims.length == 0) {
            return false;
        }
        double ix = 1.0 / ray.d.x;
        double iy = 1.0 / ray.d.y;
        double iz = 1.0 / ray.d.z;
        boolean[] negative = {ix < 0, iy < 0, iz < 0};
        int[] stack = new int[depth + 1]; // at most one pending node per level
        int top = 0;
        int node = 0;
        boolean hit = false;
        while (true) {
            if (hitsNode(node, ray, ix, iy, iz, Math.min(ray.tMax, rec.t))) {
                if (count[node] > 0) {
                    int end = first[node] + count[node];
                    for (int i = first[node]; i < end; i++) {
                        rec.tests++;
                        if (prims[i].intersect(rec, ray)) {
                            hit = true;
                            if (anyHit) {
                                return true;
                            }
                        }
                    }
                    if (top == 0) {
                        break;
                    }
                    node = stack[--top];
                } else if (negative[axisOf[node]]) {
                    stack[top++] = node + 1;
                    node = second[node];
                } else {
                    stack[top++] = second[node];
                    node = node + 1;
                }
            } else {
                if (top == 0) {
                    break;
                }
                node = stack[--top];
            }
        }
        return hit;
    }

    @Override
    public BoundingBox boundingBox() {
        return box;
    }

    @Override
    public int primitiveCount() {
        return Surface.primitiveCount(prims);
    }

    /** Number of nodes in the tree. */
    public int nodeCount() {
        return nodes;
    }
}
