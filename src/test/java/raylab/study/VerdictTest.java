package raylab.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The study's verdicts come from its decision rule applied to the numbers, not from sentences
 * written in advance: every experiment's verdict is fed synthetic measurements, then the same
 * measurements with the methods' numbers swapped, and must recommend the other method; costs
 * whose runs overlap must give "too close to call". No timing is measured here.
 */
class VerdictTest {
    /** Runs around a centre: centre·(1 ± spread), seeded. */
    static Timing.Stats runs(double centre, double spread, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] v = new double[15];
        for (int i = 0; i < v.length; i++) {
            v[i] = centre * (1 + spread * (2 * r.nextDouble() - 1));
        }
        return Timing.Stats.of(v);
    }

    static Timing.Stats[] costs(double... centres) {
        Timing.Stats[] s = new Timing.Stats[centres.length];
        for (int i = 0; i < centres.length; i++) {
            s[i] = runs(centres[i], 0.02, 100 + i);
        }
        return s;
    }

    static Timing.Stats[] reversed(Timing.Stats[] s) {
        Timing.Stats[] r = new Timing.Stats[s.length];
        for (int i = 0; i < s.length; i++) {
            r[i] = s[s.length - 1 - i];
        }
        return r;
    }

    static double[] reversed(double[] s) {
        double[] r = new double[s.length];
        for (int i = 0; i < s.length; i++) {
            r[i] = s[s.length - 1 - i];
        }
        return r;
    }

    @Test
    void onlyAccurateMethodIsRecommendedAndSwappingTheErrorsFlipsIt() {
        Timing.Stats[] cost = costs(10, 30);
        Verdict v = Verdict.decide(List.of(new Verdict.Option("A", 5, cost[0]), new Verdict.Option("B", 0, cost[1])), 0);
        assertEquals(Verdict.Kind.ONLY_ACCURATE, v.kind);
        assertEquals("B", v.recommended());
        assertTrue(v.reason("err", d -> "" + d, "0", "cost").contains("B is the only method"), v.reason("err", d -> "" + d, "0", "cost"));
        Verdict w = Verdict.decide(List.of(new Verdict.Option("A", 0, cost[0]), new Verdict.Option("B", 5, cost[1])), 0);
        assertEquals("A", w.recommended());
    }

    @Test
    void cheapestWithinToleranceWinsAndSwappingTheCostsFlipsIt() {
        Timing.Stats[] cost = costs(10, 20);
        Verdict v = Verdict.decide(List.of(new Verdict.Option("A", 0, cost[0]), new Verdict.Option("B", 0, cost[1])), 0);
        assertEquals(Verdict.Kind.CHEAPEST, v.kind);
        assertEquals("A", v.recommended());
        assertTrue(v.ratio.hi() < 1, "interval " + v.ratio.format());
        Verdict w = Verdict.decide(List.of(new Verdict.Option("A", 0, cost[1]), new Verdict.Option("B", 0, cost[0])), 0);
        assertEquals("B", w.recommended());
        assertTrue(w.headline().equals("use B"), w.headline());
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void overlappingCostsAreTooCloseToCall(long seed) {
        Timing.Stats a = runs(10, 0.3, seed);
        Timing.Stats b = runs(10.2, 0.3, seed + 1000);
        Verdict v = Verdict.decide(List.of(new Verdict.Option("A", 0, a), new Verdict.Option("B", 0, b)), 0);
        assertEquals(Verdict.Kind.TOO_CLOSE, v.kind, "seed " + seed + ": ratio " + v.ratio.format());
        assertNull(v.recommended());
        assertTrue(v.headline().startsWith(Verdict.TOO_CLOSE), v.headline());
    }

    @Test
    void aBusyMachineMakesADifferenceSmallerThanItsNoiseTooCloseToCall() {
        // Half the cost, but the calibration loop varied by 150%: 0.5 is not below 1/2.5.
        Timing.Stats a = Timing.Stats.of(runs(10, 0.02, 7).values(), 1.5);
        Timing.Stats b = Timing.Stats.of(runs(20, 0.02, 8).values(), 1.5);
        Verdict v = Verdict.decide(List.of(new Verdict.Option("A", 0, a), new Verdict.Option("B", 0, b)), 0);
        assertEquals(Verdict.Kind.TOO_CLOSE, v.kind);
        assertTrue(v.reason("err", d -> "" + d, "0", "cost").contains("machine's own variation"), v.reason("err", d -> "" + d, "0", "cost"));
        // A hundredfold difference survives the same noise.
        Timing.Stats c = Timing.Stats.of(runs(1000, 0.02, 9).values(), 1.5);
        assertEquals("A", Verdict.decide(List.of(new Verdict.Option("A", 0, a), new Verdict.Option("C", 0, c)), 0).recommended());
    }

    @Test
    void noMethodWithinToleranceNamesTheMostAccurate() {
        Timing.Stats[] cost = costs(10, 20);
        Verdict v = Verdict.decide(List.of(new Verdict.Option("A", 3, cost[0]), new Verdict.Option("B", 1, cost[1])), 0);
        assertEquals(Verdict.Kind.NONE_ACCURATE, v.kind);
        assertEquals("B", v.winner.name());
        assertNull(v.recommended());
    }

    @Test
    void bootstrapIntervalHoldsTheTrueRatioOfPairedRuns() {
        Timing.Stats a = runs(30, 0.05, 11);
        Timing.Stats b = runs(10, 0.05, 12);
        Timing.Ratio r = Timing.ratio(a, b);
        assertTrue(r.lo() < 3 && 3 < r.hi() && r.hi() - r.lo() < 0.5, "expected an interval around 3, got " + r.format());
        assertEquals(r, Timing.ratio(a, b), "same runs, same interval (seeded bootstrap)");
    }

    // ---- every experiment's verdict flips with reversed numbers ----

    @Test
    void sphereVerdictFollowsTheErrors() {
        String[] names = SphereExperiment.METHODS;
        double[] wrong = {7.3, 0};
        Timing.Stats[] cost = costs(13, 40);
        assertEquals(names[1], SphereExperiment.decide(names, wrong, cost).recommended());
        assertEquals(names[0], SphereExperiment.decide(names, reversed(wrong), reversed(cost)).recommended());
        assertEquals(Verdict.Kind.TOO_CLOSE, SphereExperiment.decide(names, new double[] {0, 0},
                new Timing.Stats[] {runs(20, 0.3, 1), runs(20, 0.3, 2)}).kind);
    }

    @Test
    void triangleVerdictFollowsTheCracks() {
        String[] names = TriangleExperiment.SHORT;
        double[] cracks = {176150, 116880, 0};
        Timing.Stats[] cost = costs(15, 10, 29);
        assertEquals(names[2], TriangleExperiment.decide(names, cracks, cost).recommended());
        assertEquals(names[0], TriangleExperiment.decide(names, reversed(cracks), reversed(cost)).recommended());
        assertEquals(Verdict.Kind.TOO_CLOSE, TriangleExperiment.decide(names, new double[] {0, 0, 0},
                new Timing.Stats[] {runs(20, 0.3, 1), runs(20, 0.3, 2), runs(20, 0.3, 3)}).kind);
    }

    @Test
    void boxVerdictFollowsTheWrongAnswers() {
        String[] names = BoxExperiment.METHODS;
        double[] wrong = {100, 0};
        Timing.Stats[] cost = costs(14, 18);
        assertEquals(names[1], BoxExperiment.decide(names, wrong, cost).recommended());
        assertEquals(names[0], BoxExperiment.decide(names, reversed(wrong), reversed(cost)).recommended());
    }

    @Test
    void shadowVerdictFollowsAcneAndLeaks() {
        String[] names = ShadowExperiment.METHODS;
        double[] worst = {61, 15, 100, 100, 100, 100, 0};
        Timing.Stats[] cost = costs(50, 50, 50, 50, 52, 55, 58);
        assertEquals(names[6], ShadowExperiment.decide(names, worst, cost).recommended());
        assertEquals(names[0], ShadowExperiment.decide(names, reversed(worst), reversed(cost)).recommended());
    }

    @Test
    void samplingVerdictFollowsTheTimeToReachTheTolerance() {
        String[] names = {"random", "stratified"};
        double[][] err = {{0.022, 0.016, 0.0085, 0.0042}, {0.022, 0.012, 0.0035, 0.0016}};
        Timing.Stats[][] time = {costs(0.001, 0.004, 0.012, 0.046), costs(0.001, 0.004, 0.012, 0.046)};
        assertEquals("stratified", SamplingExperiment.decide(names, err, time).recommended());
        double[][] swapped = {err[1], err[0]};
        assertEquals("random", SamplingExperiment.decide(names, swapped, time).recommended());
        // Both reach the tolerance at the same spp and take the same time: too close to call.
        double[][] same = {err[1], err[1]};
        Timing.Stats[][] overlapping = {{runs(1, 0.3, 1), runs(1, 0.3, 2), runs(1, 0.3, 3), runs(1, 0.3, 4)},
            {runs(1, 0.3, 5), runs(1, 0.3, 6), runs(1, 0.3, 7), runs(1, 0.3, 8)}};
        assertEquals(Verdict.Kind.TOO_CLOSE, SamplingExperiment.decide(names, same, overlapping).kind);
    }

    @Test
    void accelerationVerdictFollowsTheTimePerRay() {
        int[] counts = {1, 16, 1000};
        Verdict[] v = {AccelerationExperiment.decide(0, runs(100, 0.02, 1), runs(300, 0.02, 2)),
            AccelerationExperiment.decide(0, runs(900, 0.02, 3), runs(400, 0.02, 4)),
            AccelerationExperiment.decide(0, runs(50000, 0.02, 5), runs(900, 0.02, 6))};
        assertEquals(16, AccelerationExperiment.crossover(counts, v));
        assertEquals("use the BVH from 16 primitives on", AccelerationExperiment.headline(counts, v));
        Verdict[] rev = {AccelerationExperiment.decide(0, runs(300, 0.02, 1), runs(100, 0.02, 2)),
            AccelerationExperiment.decide(0, runs(400, 0.02, 3), runs(900, 0.02, 4)),
            AccelerationExperiment.decide(0, runs(900, 0.02, 5), runs(50000, 0.02, 6))};
        assertEquals(-1, AccelerationExperiment.crossover(counts, rev));
        Verdict[] close = {v[0], AccelerationExperiment.decide(0, runs(500, 0.3, 7), runs(510, 0.3, 8)), v[2]};
        assertEquals(1000, AccelerationExperiment.crossover(counts, close));
        assertEquals("16", AccelerationExperiment.tooClose(counts, close));
        // A BVH that changes answers is outside the tolerance, however fast.
        assertEquals("the linear group", AccelerationExperiment.decide(0.5, runs(50000, 0.02, 5), runs(900, 0.02, 6)).recommended());
    }

    @Test
    void planVerdictCallsSameWorkWhateverTheClockSays() {
        Timing.Stats[] cost = costs(10, 30);
        // The same image and the same counted work: a clock that says 3× either way changes nothing.
        assertEquals(PlanExperiment.SAME_WORK, PlanExperiment.sceneVerdict(0, 5, 5, 100, 100, cost[0], cost[1]));
        assertEquals(PlanExperiment.SAME_WORK, PlanExperiment.sceneVerdict(0, 5, 5, 100, 100, cost[1], cost[0]));
        // Less work for the plan: the rule on time decides, and swapping the times flips it.
        assertEquals("the plan", PlanExperiment.sceneVerdict(0, 5, 5, 40, 100, cost[0], cost[1]));
        assertEquals("brute force", PlanExperiment.sceneVerdict(0, 5, 9, 40, 100, cost[1], cost[0]));
        Timing.Stats a = runs(10, 0.3, 7);
        Timing.Stats b = runs(10, 0.3, 8);
        assertEquals(Verdict.TOO_CLOSE, PlanExperiment.sceneVerdict(0, 0, 0, 40, 100, a, b));
        // A differing image is never the same work, and the plan is then out.
        assertEquals("brute force", PlanExperiment.sceneVerdict(0.5, 5, 5, 100, 100, cost[0], cost[1]));
    }
}
