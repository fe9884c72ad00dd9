package raylab.study;

import java.util.Arrays;

/**
 * Careful in-process timing: warm-up until the JIT has settled, then several timed runs; the
 * median is the figure, the minimum and maximum show the spread. Each run is long enough
 * (milliseconds) for {@link System#nanoTime()} to be precise.
 */
final class Timing {
    /** A result folded into this field cannot be removed as dead code by the JIT. */
    static volatile long sink;

    private final double warmupSeconds;
    private final double runSeconds;
    private final int runs;

    Timing(double warmupSeconds, double runSeconds, int runs) {
        this.warmupSeconds = warmupSeconds;
        this.runSeconds = runSeconds;
        this.runs = runs;
    }

    /** The median, minimum and maximum of several runs of one measurement. */
    record Stats(double median, double min, double max, int runs) {
        static Stats of(double[] values) {
            double[] s = values.clone();
            Arrays.sort(s);
            int n = s.length;
            double median = n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
            return new Stats(median, s[0], s[n - 1], n);
        }

        Stats scaled(double factor) {
            return new Stats(median * factor, min * factor, max * factor, runs);
        }

        /** "12.3 (11.9–13.0)" with the given format for each number. */
        String format(String numberFormat) {
            return String.format(numberFormat + " (" + numberFormat + "–" + numberFormat + ")", median, min, max);
        }
    }

    /** Work to time: {@code run(reps)} does reps repetitions and returns a checksum. */
    @FunctionalInterface
    interface Work {
        long run(int reps);
    }

    int runs() {
        return runs;
    }

    String describe() {
        return String.format("warm-up %.2f s per method, then %d runs of about %.0f ms each, competing methods"
                + " taking turns run by run; median, min–max",
                warmupSeconds, runs, runSeconds * 1000);
    }

    /**
     * Nanoseconds per operation of {@code work}, where one repetition does {@code opsPerRep}
     * operations: calibrates the repetitions so a run lasts about runSeconds, warms up, then
     * times {@link #runs} runs.
     */
    Stats nanosPerOp(Work work, long opsPerRep) {
        int reps = 1;
        long spent;
        while (true) {
            long t0 = System.nanoTime();
            sink += work.run(reps);
            spent = System.nanoTime() - t0;
            if (spent >= runSeconds * 1e9 / 4 || reps >= 1 << 28) {
                break;
            }
            reps *= 2;
        }
        reps = (int) Math.max(1, Math.min(1L << 28, Math.round(reps * runSeconds * 1e9 / Math.max(1, spent))));
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        while (System.nanoTime() < warmEnd) {
            sink += work.run(reps);
        }
        double[] ns = new double[runs];
        for (int i = 0; i < runs; i++) {
            long t0 = System.nanoTime();
            sink += work.run(reps);
            ns[i] = (double) (System.nanoTime() - t0) / ((double) reps * opsPerRep);
        }
        return Stats.of(ns);
    }

    /**
     * Nanoseconds per operation of several competing methods, measured in turns: each is
     * calibrated and warmed up, then run i of every method follows run i of the one before, so
     * that a burst of load from elsewhere on the machine hits all of them alike.
     */
    Stats[] nanosPerOpInterleaved(Work[] works, long opsPerRep) {
        int n = works.length;
        int[] reps = new int[n];
        for (int m = 0; m < n; m++) {
            int r = 1;
            long spent;
            while (true) {
                long t0 = System.nanoTime();
                sink += works[m].run(r);
                spent = System.nanoTime() - t0;
                if (spent >= runSeconds * 1e9 / 4 || r >= 1 << 28) {
                    break;
                }
                r *= 2;
            }
            reps[m] = (int) Math.max(1, Math.min(1L << 28, Math.round(r * runSeconds * 1e9 / Math.max(1, spent))));
        }
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9 * n);
        while (System.nanoTime() < warmEnd) {
            for (int m = 0; m < n; m++) {
                sink += works[m].run(reps[m]);
            }
        }
        double[][] ns = new double[n][runs];
        for (int i = 0; i < runs; i++) {
            for (int m = 0; m < n; m++) {
                long t0 = System.nanoTime();
                sink += works[m].run(reps[m]);
                ns[m][i] = (double) (System.nanoTime() - t0) / ((double) reps[m] * opsPerRep);
            }
        }
        Stats[] out = new Stats[n];
        for (int m = 0; m < n; m++) {
            out[m] = Stats.of(ns[m]);
        }
        return out;
    }

    /** Seconds of a long task (a render, a build): {@code warmups} untimed runs, then {@code runs} timed. */
    static Stats seconds(int warmups, int runs, Runnable task) {
        for (int i = 0; i < warmups; i++) {
            task.run();
        }
        double[] s = new double[runs];
        for (int i = 0; i < runs; i++) {
            long t0 = System.nanoTime();
            task.run();
            s[i] = (System.nanoTime() - t0) / 1e9;
        }
        return Stats.of(s);
    }
}
