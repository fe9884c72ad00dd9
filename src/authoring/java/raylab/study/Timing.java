package raylab.study;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

import raylab.bench.PairedRatio;

/**
 * Careful in-process timing that says how much to trust itself.
 *
 * <ul>
 * <li>Competing methods are warmed up, then timed in turns: run i of every method follows run i
 * of the one before, so a burst of load from elsewhere hits all of them alike.
 * <li>A fixed calibration loop (integer arithmetic, no memory traffic) is timed in the same turns.
 * It does the same work every time, so the spread of its runs is the machine's own noise during
 * the measurement; the study reports it and says when it is too large for a figure to mean much.
 * <li>Cost ratios are given with a bootstrap 95% interval over the paired runs
 * ({@link #ratio}); a decision that needs one method to be cheaper uses that interval
 * ({@link Verdict}).
 * </ul>
 */
final class Timing {
    /** A result folded into this field cannot be removed as dead code by the JIT. */
    static volatile long sink;

    /** Calibration runs whose interquartile range exceeds this fraction of their median: too noisy. */
    static final double NOISY = 0.10;

    private final double warmupSeconds;
    private final double runSeconds;
    private final int runs;
    /** Relative spread (IQR / median) of the calibration loop, one entry per timed measurement. */
    private final List<Double> noise = new ArrayList<>();

    Timing(double warmupSeconds, double runSeconds, int runs) {
        this.warmupSeconds = warmupSeconds;
        this.runSeconds = runSeconds;
        this.runs = runs;
    }

    /** The runs of one measurement, and their median, quartiles, minimum and maximum. */
    record Stats(double median, double min, double max, double q1, double q3, double[] values, double noise) {
        static Stats of(double[] values) {
            return of(values, 0);
        }

        /**
         * The statistics of the runs; noise is the relative spread of the calibration loop timed
         * in the same turns (0 when there was none, as for operation counts).
         */
        static Stats of(double[] values, double noise) {
            double[] s = values.clone();
            Arrays.sort(s);
            return new Stats(quantile(s, 0.5), s[0], s[s.length - 1], quantile(s, 0.25), quantile(s, 0.75), values.clone(),
                    noise);
        }

        /** Whether the machine was too busy while these runs were taken. */
        boolean noisy() {
            return noise > NOISY;
        }

        /** A single exact figure (an operation count): no spread. */
        static Stats exact(double value) {
            return of(new double[] {value});
        }

        int runs() {
            return values.length;
        }

        Stats scaled(double factor) {
            double[] v = values.clone();
            for (int i = 0; i < v.length; i++) {
                v[i] *= factor;
            }
            return of(v, noise);
        }

        /** IQR / median: the relative spread of the runs. */
        double relativeSpread() {
            return median == 0 ? 0 : (q3 - q1) / median;
        }

        /** "12.3 (11.9–13.0)": median, then minimum–maximum, with the given format for each number. */
        String format(String numberFormat) {
            return String.format(numberFormat + " (" + numberFormat + "–" + numberFormat + ")", median, min, max);
        }
    }

    /** Linear interpolation between order statistics of sorted s. */
    static double quantile(double[] s, double q) {
        return PairedRatio.quantile(s, q);
    }

    /** A cost ratio a/b: the median of the paired run ratios and its bootstrap 95% interval. */
    record Ratio(double value, double lo, double hi) {
        /** "1.42× (1.30–1.51)". */
        String format() {
            return String.format("%.2f× (%.2f–%.2f)", value, lo, hi);
        }

        /** "+42% (+30% to +51%)". */
        String formatPercent() {
            return String.format("%+.0f%% (%+.0f%% to %+.0f%%)", 100 * (value - 1), 100 * (lo - 1), 100 * (hi - 1));
        }

        boolean below1() {
            return hi < 1;
        }

        boolean above1() {
            return lo > 1;
        }
    }

    /**
     * The ratio a/b of two measurements with a bootstrap 95% percentile interval. Runs taken in
     * turns are paired (run i of a with run i of b, which saw the same load); measurements of
     * different lengths are resampled independently. 2000 resamples, seeded, so the same runs
     * always give the same interval.
     */
    static Ratio ratio(Stats a, Stats b) {
        double[] x = a.values();
        double[] y = b.values();
        long seed = Study.SEED ^ 0x5DEECE66DL;
        if (x.length == y.length) {
            double[] r = PairedRatio.of(x, y, seed);
            return new Ratio(r[0], r[1], r[2]);
        }
        SplittableRandom random = new SplittableRandom(seed);
        int resamples = 2000;
        double[] medians = new double[resamples];
        double[] rx = new double[x.length];
        double[] ry = new double[y.length];
        for (int k = 0; k < resamples; k++) {
            for (int i = 0; i < x.length; i++) {
                rx[i] = x[random.nextInt(x.length)];
            }
            for (int i = 0; i < y.length; i++) {
                ry[i] = y[random.nextInt(y.length)];
            }
            Arrays.sort(rx);
            Arrays.sort(ry);
            medians[k] = quantile(rx, 0.5) / quantile(ry, 0.5);
        }
        Arrays.sort(medians);
        return new Ratio(a.median() / b.median(), quantile(medians, 0.025), quantile(medians, 0.975));
    }

    /** Work to time: {@code run(reps)} does reps repetitions and returns a checksum. */
    @FunctionalInterface
    interface Work {
        long run(int reps);
    }

    /** The calibration loop: reps × 4096 steps of a xorshift generator, the same work every time. */
    static long calibration(int reps) {
        long h = 0x9E3779B97F4A7C15L;
        for (int i = 0; i < reps * 4096; i++) {
            h ^= h << 13;
            h ^= h >>> 7;
            h ^= h << 17;
        }
        return h;
    }

    int runs() {
        return runs;
    }

    String describe() {
        return String.format("warm-up %.2f s per method, then %d runs of about %.0f ms each, competing methods and a"
                + " calibration loop taking turns run by run; median, min–max; cost ratios with a bootstrap 95%%"
                + " interval over the paired runs", warmupSeconds, runs, runSeconds * 1000);
    }

    /** The calibration spreads measured so far, one per timed measurement. */
    List<Double> noise() {
        return List.copyOf(noise);
    }

    /** The median calibration spread over the run (0 if nothing was timed). */
    double medianNoise() {
        if (noise.isEmpty()) {
            return 0;
        }
        double[] v = noise.stream().mapToDouble(Double::doubleValue).toArray();
        Arrays.sort(v);
        return quantile(v, 0.5);
    }

    double worstNoise() {
        return noise.stream().mapToDouble(Double::doubleValue).max().orElse(0);
    }

    /** One sentence on the machine's noise during the run, and whether it was too large. */
    String noiseSentence() {
        double med = medianNoise();
        double worst = worstNoise();
        String s = String.format("the calibration loop, timed in turns with every measurement, varied by %.1f%% (interquartile"
                + " range over median; median over %d measurements, worst %.1f%%)", 100 * med, noise.size(), 100 * worst);
        if (med > NOISY) {
            return s + ". **The machine was too busy for the timings to mean much**: seconds and ratios below are"
                    + " unreliable beyond their intervals; the operation counts and the accuracy figures are not affected.";
        }
        if (worst > NOISY) {
            return s + ". Some measurements ran while the machine was busy (spread above "
                    + String.format("%.0f%%", 100 * NOISY) + "); their intervals are wider.";
        }
        return s + String.format(": quiet enough (below %.0f%%) for the intervals to be trusted.", 100 * NOISY);
    }

    private int calibrate(Work work) {
        int r = 1;
        long spent;
        while (true) {
            long t0 = System.nanoTime();
            sink += work.run(r);
            spent = System.nanoTime() - t0;
            if (spent >= runSeconds * 1e9 / 4 || r >= 1 << 28) {
                break;
            }
            r *= 2;
        }
        return (int) Math.max(1, Math.min(1L << 28, Math.round(r * runSeconds * 1e9 / Math.max(1, spent))));
    }

    /** Nanoseconds per operation of one method (with the calibration loop in turns). */
    Stats nanosPerOp(Work work, long opsPerRep) {
        return nanosPerOpInterleaved(new Work[] {work}, opsPerRep)[0];
    }

    /**
     * Nanoseconds per operation of several competing methods, measured in turns: each is
     * calibrated and warmed up, then run i of every method (and of the calibration loop) follows
     * run i of the one before, so that a burst of load from elsewhere on the machine hits all of
     * them alike.
     */
    Stats[] nanosPerOpInterleaved(Work[] works, long opsPerRep) {
        long[] ops = new long[works.length];
        Arrays.fill(ops, opsPerRep);
        return nanosPerOpInterleaved(works, ops);
    }

    /** As {@link #nanosPerOpInterleaved(Work[], long)}, with each method's own operations per repetition. */
    Stats[] nanosPerOpInterleaved(Work[] works, long[] opsPerRep) {
        int n = works.length;
        Work[] all = Arrays.copyOf(works, n + 1);
        all[n] = Timing::calibration;
        int[] reps = new int[n + 1];
        for (int m = 0; m <= n; m++) {
            reps[m] = calibrate(all[m]);
        }
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9 * n);
        while (System.nanoTime() < warmEnd) {
            for (int m = 0; m <= n; m++) {
                sink += all[m].run(reps[m]);
            }
        }
        double[][] ns = new double[n + 1][runs];
        for (int i = 0; i < runs; i++) {
            // The order rotates from run to run, so that no method always comes first (right after
            // the previous run used up its share of the processor) or last.
            for (int k = 0; k <= n; k++) {
                int m = (k + i) % (n + 1);
                long t0 = System.nanoTime();
                sink += all[m].run(reps[m]);
                ns[m][i] = (double) (System.nanoTime() - t0) / ((double) reps[m] * (m < n ? opsPerRep[m] : 1));
            }
        }
        double spread = Stats.of(ns[n]).relativeSpread();
        noise.add(spread);
        Stats[] out = new Stats[n];
        for (int m = 0; m < n; m++) {
            out[m] = Stats.of(ns[m], spread);
        }
        return out;
    }

    /**
     * Seconds of long tasks (renders, builds), in turns: {@code warmups} untimed rounds, then
     * {@code runs} rounds in which every task runs once, followed by the calibration loop.
     */
    Stats[] secondsInterleaved(int warmups, int runs, Runnable... tasks) {
        int n = tasks.length;
        for (int i = 0; i < warmups; i++) {
            for (Runnable t : tasks) {
                t.run();
            }
        }
        double[][] s = new double[n][runs];
        double[] cal = new double[runs];
        // The calibration loop lasts about as long as one task, so that it sees the same kind of
        // interruptions (a task of 20 ms is preempted far more often than a loop of 1 ms).
        int perRun = calibrate(Timing::calibration);
        int calReps = -1;
        for (int i = 0; i < runs; i++) {
            // Rotating order, as in nanosPerOpInterleaved; the calibration loop is slot n.
            for (int k = 0; k <= n; k++) {
                int m = (k + i) % (n + 1);
                if (m < n) {
                    long t0 = System.nanoTime();
                    tasks[m].run();
                    s[m][i] = (System.nanoTime() - t0) / 1e9;
                } else {
                    if (calReps < 0) {
                        // First round: the calibration slot comes last, after every task's first run.
                        double mean = 0;
                        for (int j = 0; j < n; j++) {
                            mean += s[j][0] / n;
                        }
                        calReps = (int) Math.max(1, Math.min(1L << 24, Math.round(perRun * mean / runSeconds)));
                    }
                    long t0 = System.nanoTime();
                    sink += calibration(calReps);
                    cal[i] = System.nanoTime() - t0;
                }
            }
        }
        double spread = Stats.of(cal).relativeSpread();
        if (runs >= 3) {
            noise.add(spread);
        }
        Stats[] out = new Stats[n];
        for (int m = 0; m < n; m++) {
            out[m] = Stats.of(s[m], spread);
        }
        return out;
    }

    /** Seconds of one long task: {@code warmups} untimed runs, then {@code runs} timed. */
    Stats seconds(int warmups, int runs, Runnable task) {
        return secondsInterleaved(warmups, runs, task)[0];
    }
}
