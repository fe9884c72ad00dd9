package raylab.surface;

import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.testing.Check;

/** Milestone box: {@link Box#intersect}. Run with {@code ./mvnw test -Dgroups=box}. */
@Tag("box")
class BoxTest {
    static final Lambertian WHITE = new Lambertian(new Color(1, 1, 1), Color.BLACK, "white");
    /** The box 1 ≤ x ≤ 2, 2 ≤ y ≤ 4, 3 ≤ z ≤ 7 (centre (1.5, 3, 5)). */
    static final Box BOX = new Box(new Vec3(1, 2, 3), new Vec3(2, 4, 7), WHITE, "box");

    /** From (1.5,3,10) along −z: the box is entered at z = 7 (t = 3) and left at z = 3 (t = 7). */
    static final Vec3 P = new Vec3(1.5, 3, 10);
    static final Vec3 DOWN_Z = new Vec3(0, 0, -1);

    static Vec3 v(double x, double y, double z) {
        return new Vec3(x, y, z);
    }

    static Stream<Arguments> faces() {
        return Stream.of(
                // From x = −1 along +x: the plane x = 1 is 2 away.
                Arguments.of("x = 1 (min x)", new Ray(v(-1, 3.5, 4), v(1, 0, 0)),
                        2.0, v(1, 3.5, 4), v(-1, 0, 0)),
                // From x = 5 along (−3,0,0): x = 2 is reached at t = 3/3 = 1.
                Arguments.of("x = 2 (max x)", new Ray(v(5, 2.5, 6), v(-3, 0, 0)),
                        1.0, v(2, 2.5, 6), v(1, 0, 0)),
                // From y = 0 along (0,0.5,0): y = 2 is reached at t = 2/0.5 = 4.
                Arguments.of("y = 2 (min y)", new Ray(v(1.25, 0, 5), v(0, 0.5, 0)),
                        4.0, v(1.25, 2, 5), v(0, -1, 0)),
                // From y = 10 along (0,−2,0): y = 4 is reached at t = 6/2 = 3.
                Arguments.of("y = 4 (max y)", new Ray(v(1.75, 10, 3.5), v(0, -2, 0)),
                        3.0, v(1.75, 4, 3.5), v(0, 1, 0)),
                // From z = −1 along (0.1,0.2,2): z = 3 at t = 4/2 = 2, where x = 1.2 + 0.2 and
                // y = 2.5 + 0.4.
                Arguments.of("z = 3 (min z)", new Ray(v(1.2, 2.5, -1), v(0.1, 0.2, 2)),
                        2.0, v(1.4, 2.9, 3), v(0, 0, -1)),
                Arguments.of("z = 7 (max z)", new Ray(P, DOWN_Z), 3.0, v(1.5, 3, 7), v(0, 0, 1)));
    }

    @ParameterizedTest(name = "face {0}")
    @MethodSource("faces")
    @DisplayName("each of the 6 faces is hit with its own outward normal")
    void eachFace(String face, Ray ray, double t, Vec3 point, Vec3 normal) {
        Check.hit(BOX, ray, t, point, normal);
    }

    @Test
    @DisplayName("oblique ray: the entry is the last of the three slab entries (here the y slab)")
    void lastEntryWins() {
        // From (0.5,6,5) along (1,−2,0): the x slab is entered at t = 0.5 and left at 1.5,
        // the y slab entered at t = 1 (y = 4) and left at 2 (y = 2); z is always inside.
        // t_enter = max(0.5, 1) = 1 ≤ t_exit = min(1.5, 2): hit on the face y = 4 at x = 1.5.
        Check.hit(BOX, new Ray(v(0.5, 6, 5), v(1, -2, 0)), 1, v(1.5, 4, 5), v(0, 1, 0),
                "t_enter is the largest of the slab entries, t_exit the smallest of the exits");
    }

    @Test
    @DisplayName("oblique miss: the last entry comes after the first exit")
    void entryAfterExitMisses() {
        // From (0,6,5) along (1,−0.8,0): x slab for t in [1, 2], y slab for t in [2.5, 5].
        // t_enter = 2.5 > t_exit = 2: the slabs never overlap, no hit.
        Check.miss(BOX, new Ray(v(0, 6, 5), v(1, -0.8, 0)), "no hit when t_enter > t_exit");
    }

    @Test
    @DisplayName("a ray starting inside hits the exit face, normal outward")
    void startsInside() {
        // From the centre (1.5,3,5) along (1,1,0): x = 2 at t = 0.5 comes before y = 4 at t = 1.
        Check.hit(BOX, new Ray(v(1.5, 3, 5), v(1, 1, 0)), 0.5, v(2, 3.5, 5), v(1, 0, 0));
    }

    @Test
    @DisplayName("a box behind the ray's origin is not hit")
    void behind() {
        Check.miss(BOX, new Ray(P, v(0, 0, 1)), "t_enter and t_exit are both negative here");
    }

    @Test
    @DisplayName("d parallel to two slabs, inside both: hit")
    void parallelInsideSlabs() {
        // d has zero x and y components; p.x = 1.9 is inside [1, 2], p.y = 3 inside [2, 4].
        Check.hitWhen(BOX, new Ray(v(1.9, 3, 10), DOWN_Z), 3, v(1.9, 3, 7), v(0, 0, 1),
                Check.Hint.zeroComponent("when d_x = 0, the ray is inside the x slab for every t (if min x ≤ p_x ≤ max x)"));
    }

    @Test
    @DisplayName("d parallel to a slab, outside it: miss")
    void parallelOutsideSlab() {
        // p.x = 2.1 is outside [1, 2] and d_x = 0: the ray never gets into the x slab.
        Check.missWhen(BOX, new Ray(v(2.1, 3, 10), DOWN_Z),
                Check.Hint.zeroComponent("when d_x = 0 and p_x is outside [min x, max x], the ray never enters the box"));
        // p.y = 5 is outside [2, 4] and d_y = 0 (the ray runs along +x above the box).
        Check.miss(BOX, new Ray(v(0, 5, 5), v(1, 0, 0)), null);
    }

    @ParameterizedTest(name = "d scaled by {0}")
    @ValueSource(doubles = {0.01, 0.5, 2, 100})
    @DisplayName("d need not have length 1: scaling d by a divides t by a, same point")
    void unnormalizedDirection(double a) {
        Check.hit(BOX, new Ray(P, DOWN_Z.times(a)), 3 / a, v(1.5, 3, 7), v(0, 0, 1));
    }

    @Test
    @DisplayName("tMax just above the entry: counted; just below: not")
    void tMaxBound() {
        Check.hit(BOX, new Ray(P, DOWN_Z, 0, 3 + 1e-6), 3, v(1.5, 3, 7), v(0, 0, 1));
        Check.miss(BOX, new Ray(P, DOWN_Z, 0, 3 - 1e-6), "t = 3 > tMax does not count");
    }

    @Test
    @DisplayName("tMin just below the entry: counted; just past it: the exit (t = 7) is the hit")
    void tMinBound() {
        Check.hit(BOX, new Ray(P, DOWN_Z, 3 - 1e-6, Double.POSITIVE_INFINITY),
                3, v(1.5, 3, 7), v(0, 0, 1));
        Check.hit(BOX, new Ray(P, DOWN_Z, 3 + 1e-6, Double.POSITIVE_INFINITY),
                7, v(1.5, 3, 3), v(0, 0, -1));
        Check.miss(BOX, new Ray(P, DOWN_Z, 7 + 1e-6, Double.POSITIVE_INFINITY), null);
    }

    @Test
    @DisplayName("a miss leaves a record that holds another hit exactly as it was")
    void missLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(100), BOX, new Ray(v(2.1, 3, 10), DOWN_Z), null);
    }

    @Test
    @DisplayName("a hit farther than the record's t (3 > 2) leaves the record as it was")
    void fartherHitLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(2), BOX, new Ray(P, DOWN_Z), null);
    }

    @Test
    @DisplayName("a hit closer than the record's t (3 < 4) replaces it")
    void closerHitReplacesRecord() {
        Check.hit(Check.recordWithHitAt(4), BOX, new Ray(P, DOWN_Z), 3, v(1.5, 3, 7), v(0, 0, 1),
                null);
    }

    @Test
    @DisplayName("a ray just inside an edge hits, just outside misses")
    void nearTheEdge() {
        Check.hit(BOX, new Ray(v(1.999, 3.999, 10), DOWN_Z), 3, v(1.999, 3.999, 7), v(0, 0, 1));
        Check.miss(BOX, new Ray(v(2.001, 3.999, 10), DOWN_Z), null);
    }
}
