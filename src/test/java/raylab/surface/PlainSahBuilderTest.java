package raylab.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link BvhBuilder} against a plain second builder written from its stated rule alone: binned
 * SAH, 12 bins along the longest axis of the centroids, split costs from unions recomputed from
 * scratch for every split (no sweeps), stable partition by list filtering, leaves of at most 4
 * unless splitting costs more (up to 8) or the centroids coincide. Both must give the same tree,
 * node for node, on seeded random boxes of many shapes: the fast builder's sweeps, reused arrays
 * and parallel subtrees change nothing.
 */
class PlainSahBuilderTest {
    static Stream<Long> seeds() {
        return IntStream.range(0, 40).mapToObj(i -> 1000L + i);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void theFastBuilderMakesThePlainBuildersTree(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        int n = 1 + r.nextInt(seed % 10 == 0 ? 5000 : 400);
        double[] box = new double[6 * n];
        int shape = r.nextInt(5);
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                // Shapes: spread out, flat in y, on a coarse grid (many equal centroids), tiny, unit
                // cubes on a grid (symmetric, so equal split costs, where the first must win).
                double c = shape >= 2 && shape != 3 ? r.nextInt(6) : r.nextDouble(-100, 100) * (shape == 1 && k == 1 ? 1e-3 : 1);
                double h = shape == 3 ? r.nextDouble(0, 1e-6) : shape == 4 ? 0.5 : r.nextDouble(0, 2);
                box[6 * i + k] = c - h;
                box[6 * i + 3 + k] = c + h;
            }
        }
        List<int[]> plain = new ArrayList<>();
        List<Integer> order = new ArrayList<>();
        List<Integer> all = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            all.add(i);
        }
        plainBuild(box, all, plain, order);
        BvhNodes fast = BvhBuilder.build(box, n, 1 + r.nextInt(3));
        String where = "seed " + seed + ", " + n + " boxes, shape " + shape;
        assertEquals(plain.size(), fast.count, "node count, " + where);
        assertEquals(order.toString(), Arrays.toString(fast.order), "leaf order of the primitives, " + where);
        int[] dfs = new int[BvhBuilder.STRIDE * plain.size()];
        for (int i = 0; i < plain.size(); i++) {
            System.arraycopy(plain.get(i), 0, dfs, BvhBuilder.STRIDE * i, BvhBuilder.STRIDE);
        }
        BvhNodes expected = new BvhNodes(dfs, plain.size(), fast.depth, fast.order);
        assertEquals(Arrays.toString(expected.inner), Arrays.toString(fast.inner), "inner nodes, " + where);
        assertEquals(Arrays.toString(expected.leaf), Arrays.toString(fast.leaf), "leaves, " + where);
    }

    /** Appends the depth-first nodes of the subtree over {@code prims} (eight ints each, as BvhBuilder's). */
    private static void plainBuild(double[] box, List<Integer> prims, List<int[]> nodes, List<Integer> order) {
        int[] node = new int[BvhBuilder.STRIDE];
        nodes.add(node);
        double[] b = union(box, prims);
        double[] c = new double[] {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int p : prims) {
            for (int k = 0; k < 3; k++) {
                double m = centroid(box, p, k);
                c[k] = Math.min(c[k], m);
                c[3 + k] = Math.max(c[3 + k], m);
            }
        }
        for (int k = 0; k < 3; k++) {
            node[k] = Float.floatToRawIntBits(BvhBuilder.down(b[k]));
            node[3 + k] = Float.floatToRawIntBits(BvhBuilder.up(b[3 + k]));
        }
        double ex = c[3] - c[0];
        double ey = c[4] - c[1];
        double ez = c[5] - c[2];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        double cmin = c[axis];
        double cext = c[3 + axis] - cmin;
        int n = prims.size();
        int split = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        if (n > BvhBuilder.MAX_LEAF && cext > 0) {
            for (int s = 1; s < BvhBuilder.BINS; s++) {
                List<Integer> left = side(box, prims, axis, cmin, cext, s, true);
                List<Integer> right = side(box, prims, axis, cmin, cext, s, false);
                if (left.isEmpty() || right.isEmpty()) {
                    continue;
                }
                double cost = left.size() * halfArea(union(box, left)) + right.size() * halfArea(union(box, right));
                if (cost < bestCost) {
                    bestCost = cost;
                    split = s;
                }
            }
        }
        boolean leaf = split < 0 || (n <= 2 * BvhBuilder.MAX_LEAF && bestCost >= n * halfArea(b));
        if (leaf) {
            node[6] = order.size();
            node[7] = n;
            order.addAll(prims);
            return;
        }
        plainBuild(box, side(box, prims, axis, cmin, cext, split, true), nodes, order);
        node[6] = nodes.size();
        node[7] = -(axis + 1);
        plainBuild(box, side(box, prims, axis, cmin, cext, split, false), nodes, order);
    }

    private static List<Integer> side(double[] box, List<Integer> prims, int axis, double cmin, double cext, int split,
            boolean left) {
        List<Integer> out = new ArrayList<>();
        for (int p : prims) {
            int bin = (int) (BvhBuilder.BINS * ((centroid(box, p, axis) - cmin) / cext));
            bin = Math.max(0, Math.min(BvhBuilder.BINS - 1, bin));
            if ((bin < split) == left) {
                out.add(p);
            }
        }
        return out;
    }

    private static double centroid(double[] box, int p, int k) {
        return (box[6 * p + k] + box[6 * p + 3 + k]) * 0.5;
    }

    private static double[] union(double[] box, List<Integer> prims) {
        double[] u = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int p : prims) {
            for (int k = 0; k < 3; k++) {
                u[k] = Math.min(u[k], box[6 * p + k]);
                u[3 + k] = Math.max(u[3 + k], box[6 * p + 3 + k]);
            }
        }
        return u;
    }

    private static double halfArea(double[] b) {
        double x = b[3] - b[0];
        double y = b[4] - b[1];
        double z = b[5] - b[2];
        return x * y + y * z + z * x;
    }

    @Test
    void theParallelBuildMakesTheSequentialTreeNodeForNode() {
        SplittableRandom r = new SplittableRandom(99);
        int n = 3 * BvhBuilder.PARALLEL_MIN;
        double[] box = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                double c = r.nextDouble(-100, 100) * (k == 1 ? 0.1 : 1);
                double h = r.nextDouble(0, 0.5);
                box[6 * i + k] = c - h;
                box[6 * i + 3 + k] = c + h;
            }
        }
        BvhNodes one = BvhBuilder.build(box, n, 1);
        BvhNodes four = BvhBuilder.build(box, n, 4);
        assertEquals(one.count, four.count, "node count");
        assertEquals(one.depth, four.depth, "depth");
        assertTrue(java.util.Arrays.equals(one.order, four.order), "primitive order");
        assertTrue(java.util.Arrays.equals(one.inner, four.inner), "inner nodes");
        assertTrue(java.util.Arrays.equals(one.leaf, four.leaf), "leaves");
    }
}
