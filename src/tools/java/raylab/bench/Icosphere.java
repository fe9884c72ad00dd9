package raylab.bench;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The procedural benchmark mesh of the shared Embree harness ({@code meshgen.py}): an icosphere
 * subdivided L times (20·4^L triangles), each vertex moved radially by
 * 1 + 0.15·sin(7x)·sin(9y)·sin(5z). Same vertices (up to the 7 decimals the OBJ file keeps) and
 * the same faces in the same order, so benchmarks can run without the file.
 */
public final class Icosphere {
    private Icosphere() {
    }

    /** The triangles as a, b, c (nine numbers each). */
    public static double[] triangles(int levels) {
        double t = (1 + Math.sqrt(5)) / 2;
        List<double[]> v = new ArrayList<>();
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] p : base) {
            v.add(unit(p));
        }
        int[][] f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
            {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        List<int[]> faces = new ArrayList<>(List.of(f));
        for (int l = 0; l < levels; l++) {
            Map<Long, Integer> cache = new HashMap<>();
            List<int[]> next = new ArrayList<>(4 * faces.size());
            for (int[] abc : faces) {
                int ab = mid(v, cache, abc[0], abc[1]);
                int bc = mid(v, cache, abc[1], abc[2]);
                int ca = mid(v, cache, abc[2], abc[0]);
                next.add(new int[] {abc[0], ab, ca});
                next.add(new int[] {abc[1], bc, ab});
                next.add(new int[] {abc[2], ca, bc});
                next.add(new int[] {ab, bc, ca});
            }
            faces = next;
        }
        double[] moved = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) {
            double[] p = v.get(i);
            double r = 1 + 0.15 * Math.sin(7 * p[0]) * Math.sin(9 * p[1]) * Math.sin(5 * p[2]);
            for (int k = 0; k < 3; k++) {
                moved[3 * i + k] = Math.round(p[k] * r * 1e7) / 1e7;
            }
        }
        double[] out = new double[9 * faces.size()];
        for (int i = 0; i < faces.size(); i++) {
            for (int j = 0; j < 3; j++) {
                System.arraycopy(moved, 3 * faces.get(i)[j], out, 9 * i + 3 * j, 3);
            }
        }
        return out;
    }

    private static int mid(List<double[]> v, Map<Long, Integer> cache, int a, int b) {
        long key = a < b ? ((long) a << 32) | b : ((long) b << 32) | a;
        Integer m = cache.get(key);
        if (m == null) {
            double[] p = v.get(a);
            double[] q = v.get(b);
            v.add(unit(new double[] {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2}));
            m = v.size() - 1;
            cache.put(key, m);
        }
        return m;
    }

    private static double[] unit(double[] p) {
        double n = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return new double[] {p[0] / n, p[1] / n, p[2] / n};
    }
}
