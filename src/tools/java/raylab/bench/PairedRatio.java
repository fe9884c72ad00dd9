package raylab.bench;

import java.util.Arrays;
import java.util.SplittableRandom;

/**
 * The ratio of two methods timed in turns (run i of one beside run i of the other, so both saw the
 * same load): the median of the paired ratios a[i]/b[i], with a bootstrap 95% percentile interval
 * (2000 resamples of the pairs, seeded, so the same runs always give the same interval). Used by
 * {@code raylab bench} and by the study's timing.
 */
public final class PairedRatio {
    private PairedRatio() {
    }

    /** {median, low, high} of a[i]/b[i]; the arrays must have the same, non-zero length. */
    public static double[] of(double[] a, double[] b, long seed) {
        if (a.length != b.length || a.length == 0) {
            throw new IllegalArgumentException("paired runs expected, got " + a.length + " and " + b.length);
        }
        int n = a.length;
        SplittableRandom random = new SplittableRandom(seed);
        int resamples = 2000;
        double[] medians = new double[resamples];
        double[] r = new double[n];
        for (int k = 0; k < resamples; k++) {
            for (int i = 0; i < n; i++) {
                int j = random.nextInt(n);
                r[i] = a[j] / b[j];
            }
            Arrays.sort(r);
            medians[k] = quantile(r, 0.5);
        }
        Arrays.sort(medians);
        double[] all = new double[n];
        for (int i = 0; i < n; i++) {
            all[i] = a[i] / b[i];
        }
        Arrays.sort(all);
        return new double[] {quantile(all, 0.5), quantile(medians, 0.025), quantile(medians, 0.975)};
    }

    /** The q-quantile of sorted values, interpolating linearly between neighbours. */
    public static double quantile(double[] sorted, double q) {
        double pos = q * (sorted.length - 1);
        int i = (int) Math.floor(pos);
        int j = Math.min(sorted.length - 1, i + 1);
        return sorted[i] + (pos - i) * (sorted[j] - sorted[i]);
    }
}
