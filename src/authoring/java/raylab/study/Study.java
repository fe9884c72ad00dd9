package raylab.study;

import java.nio.file.Path;

/** What every experiment needs: where to write, how thorough to be, how to time. */
final class Study {
    final Path out;
    final boolean quick;
    final Timing timing;
    final Report report;
    /** Every random choice of the study derives from this seed, so a run can be repeated. */
    static final long SEED = 20240521L;

    Study(Path out, boolean quick, Report report) {
        this.out = out;
        this.quick = quick;
        this.report = report;
        this.timing = quick ? new Timing(0.05, 0.002, 15) : new Timing(0.3, 0.008, 31);
    }

    /** quick ? q : full. */
    int pick(int full, int q) {
        return quick ? q : full;
    }

    void log(String message) {
        System.err.println("study: " + message);
    }
}
