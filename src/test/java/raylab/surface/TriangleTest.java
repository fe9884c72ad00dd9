package raylab.surface;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.testing.Check;

/**
 * Milestone triangle: {@link Triangle#intersect}.
 * Run with {@code ./mvnw test -Dgroups=triangle}.
 */
@Tag("triangle")
class TriangleTest {
    static final Lambertian WHITE = new Lambertian(new Color(1, 1, 1), Color.BLACK, "white");
    /** a = (0,0,0), b = (1,0,0), c = (0,1,0): n = (b − a) × (c − a) = (0,0,1). */
    static final Triangle TRI = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0), WHITE, "triangle");
    static final Vec3 UP = v(0, 0, 1);
    static final Vec3 DOWN_Z = v(0, 0, -1);

    static Vec3 v(double x, double y, double z) {
        return new Vec3(x, y, z);
    }

    /** The ray that comes down the z axis from height 5 onto the point (x, y, 0). */
    static Ray downOnto(double x, double y) {
        return new Ray(v(x, y, 5), DOWN_Z);
    }

    @Test
    @DisplayName("a ray onto the inside of the triangle hits at t = 5, normal (0,0,1)")
    void plainHit() {
        Check.hit(TRI, downOnto(0.25, 0.25), 5, v(0.25, 0.25, 0), UP);
    }

    @Test
    @DisplayName("hit from behind: the normal is still (b − a) × (c − a), normalized")
    void hitFromBehind() {
        Check.hitWhen(TRI, new Ray(v(0.25, 0.25, -5), UP), 5, v(0.25, 0.25, 0), UP,
                Check.Hint.normal("record the normal (b − a) × (c − a) / ‖…‖ whichever side the ray comes from"));
    }

    @Test
    @DisplayName("a slanted triangle: plane 6x + 3y + 2z = 6, hit at t = 6/11")
    void slantedTriangle() {
        // a = (1,0,0), b = (0,2,0), c = (0,0,3): (b − a) × (c − a) = (−1,2,0) × (−1,0,3)
        // = (6, 3, 2), of length 7. The ray from the origin along (1,1,1) meets the plane
        // 6x + 3y + 2z = 6 where 11t = 6. The point (6,6,6)/11 = (6/11)a + (3/11)b + (2/11)c
        // is inside: all three barycentric coordinates are positive.
        Triangle tri = new Triangle(v(1, 0, 0), v(0, 2, 0), v(0, 0, 3), WHITE, "slanted triangle");
        double t = 6.0 / 11;
        Check.hit(tri, new Ray(v(0, 0, 0), v(1, 1, 1)), t, v(t, t, t),
                v(6 / 7.0, 3 / 7.0, 2 / 7.0));
    }

    @Test
    @DisplayName("just outside edge ab (y < 0): miss")
    void outsideEdgeAB() {
        Check.miss(TRI, downOnto(0.5, -0.01), "the point is on the outer side of edge a→b");
    }

    @Test
    @DisplayName("just outside edge bc (x + y > 1): miss")
    void outsideEdgeBC() {
        Check.miss(TRI, downOnto(0.51, 0.5), "the point is on the outer side of edge b→c");
    }

    @Test
    @DisplayName("just outside edge ca (x < 0): miss")
    void outsideEdgeCA() {
        Check.miss(TRI, downOnto(-0.01, 0.5), "the point is on the outer side of edge c→a");
    }

    @Test
    @DisplayName("just inside each of the three edges: hit")
    void insideNearEdges() {
        Check.hit(TRI, downOnto(0.5, 0.01), 5, v(0.5, 0.01, 0), UP);
        Check.hit(TRI, downOnto(0.49, 0.5), 5, v(0.49, 0.5, 0), UP);
        Check.hit(TRI, downOnto(0.01, 0.5), 5, v(0.01, 0.5, 0), UP);
    }

    @Test
    @DisplayName("a point of the plane far outside the triangle: miss")
    void farOutside() {
        Check.miss(TRI, downOnto(3, 3), null);
    }

    @Test
    @DisplayName("a ray parallel to the plane (d·n = 0) misses")
    void parallel() {
        Check.miss(TRI, new Ray(v(-1, 0.25, 1), v(1, 0, 0)),
                "when d·n = 0 the ray never meets the plane: return false before dividing");
    }

    @Test
    @DisplayName("a triangle behind the ray's origin is not hit")
    void behind() {
        Check.miss(TRI, new Ray(v(0.25, 0.25, 5), UP), "t = −5 < tMin: behind the origin");
    }

    @ParameterizedTest(name = "d scaled by {0}")
    @ValueSource(doubles = {0.01, 0.5, 2, 100})
    @DisplayName("d need not have length 1: scaling d by a divides t by a, same point")
    void unnormalizedDirection(double a) {
        Check.hit(TRI, new Ray(v(0.25, 0.25, 5), DOWN_Z.times(a)), 5 / a, v(0.25, 0.25, 0), UP);
    }

    @Test
    @DisplayName("tMax and tMin just around t = 5: counted inside the range, not outside")
    void rangeBounds() {
        Vec3 p = v(0.25, 0.25, 5);
        Vec3 x = v(0.25, 0.25, 0);
        Check.hit(TRI, new Ray(p, DOWN_Z, 0, 5 + 1e-6), 5, x, UP);
        Check.hit(TRI, new Ray(p, DOWN_Z, 5 - 1e-6, 10), 5, x, UP);
        Check.miss(TRI, new Ray(p, DOWN_Z, 0, 5 - 1e-6), "t = 5 > tMax does not count");
        Check.miss(TRI, new Ray(p, DOWN_Z, 5 + 1e-6, 10), "t = 5 < tMin does not count");
    }

    @Test
    @DisplayName("a miss leaves a record that holds another hit exactly as it was")
    void missLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(100), TRI, downOnto(0.6, 0.6), null);
    }

    @Test
    @DisplayName("a hit farther than the record's t (5 > 4) leaves the record as it was")
    void fartherHitLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(4), TRI, downOnto(0.25, 0.25), null);
    }

    @Test
    @DisplayName("a hit closer than the record's t (5 < 6) replaces it")
    void closerHitReplacesRecord() {
        Check.hit(Check.recordWithHitAt(6), TRI, downOnto(0.25, 0.25), 5, v(0.25, 0.25, 0), UP,
                null);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    @DisplayName("random triangles and rays, checked against a barycentric solve (Cramer's rule)")
    void random(long seed) {
        Random rnd = new Random(seed);
        int done = 0;
        while (done < 40) {
            Vec3 a = randomPoint(rnd);
            Vec3 b = randomPoint(rnd);
            Vec3 c = randomPoint(rnd);
            Vec3 n = b.minus(a).cross(c.minus(a));
            Vec3 d = randomPoint(rnd);
            // Aim at a point of the plane near the triangle (inside about half the time).
            Vec3 aim = a.plus(b.minus(a).times(rnd.nextDouble() * 1.4 - 0.2))
                    .plus(c.minus(a).times(rnd.nextDouble() * 1.4 - 0.2));
            Vec3 p = aim.minus(d.times(0.5 + rnd.nextDouble() * 5));
            // Keep well-shaped cases: a triangle that is not a sliver, a ray not nearly
            // parallel to its plane.
            double longest = Math.max(b.minus(a).length(), Math.max(c.minus(b).length(),
                    a.minus(c).length()));
            if (n.length() < 0.2 * longest * longest
                    || Math.abs(d.normalize().dot(n.normalize())) < 0.2) {
                continue;
            }
            // Solve p + t·d = a + β(b − a) + γ(c − a), i.e. [−d, b − a, c − a]·(t, β, γ) = p − a,
            // by Cramer's rule: each unknown is a ratio of 3×3 determinants.
            Vec3 e1 = b.minus(a);
            Vec3 e2 = c.minus(a);
            Vec3 rhs = p.minus(a);
            double det = det(d.negate(), e1, e2);
            double t = det(rhs, e1, e2) / det;
            double beta = det(d.negate(), rhs, e2) / det;
            double gamma = det(d.negate(), e1, rhs) / det;
            double alpha = 1 - beta - gamma;
            double nearest = Math.min(alpha, Math.min(beta, gamma));
            if (Math.abs(nearest) < 0.02) {
                continue; // too close to an edge to be fair to every method
            }
            Triangle tri = new Triangle(a, b, c, WHITE, "random triangle #" + done + " of seed "
                    + seed + " (barycentric " + alpha + ", " + beta + ", " + gamma + ")");
            Ray ray = new Ray(p, d);
            if (nearest > 0) {
                Check.hit(tri, ray, t, ray.evaluate(t), n.normalize());
            } else {
                Check.miss(tri, ray, "a barycentric coordinate is negative: outside");
            }
            done++;
        }
    }

    static Vec3 randomPoint(Random rnd) {
        return new Vec3(rnd.nextDouble() * 10 - 5, rnd.nextDouble() * 10 - 5,
                rnd.nextDouble() * 10 - 5);
    }

    /** The determinant of the 3×3 matrix with columns u, v, w: u · (v × w). */
    static double det(Vec3 u, Vec3 v, Vec3 w) {
        return u.dot(v.cross(w));
    }
}
