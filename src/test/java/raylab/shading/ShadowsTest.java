package raylab.shading;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.surface.Box;
import raylab.surface.Group;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.testing.Check;

/**
 * Milestone shadows: {@link Shadows#isShadowed}. Run with {@code ./mvnw test -Dgroups=shadows}.
 * (The scenes use spheres and boxes, so those milestones must work too.)
 */
@Tag("shadows")
class ShadowsTest {
    static final Lambertian WHITE = new Lambertian(new Color(1, 1, 1), Color.BLACK, "white");
    static final Vec3 UP = new Vec3(0, 1, 0);
    static final String ACNE = "shadow acne: the point lies on (or a hair below) its own surface;"
            + " start the shadow ray off the surface (move the origin, or raise tMin)";

    /** A floor, the box −10 ≤ x,z ≤ 10, −1 ≤ y ≤ 0, whose top face is the plane y = 0. */
    static final Box FLOOR = new Box(new Vec3(-10, -1, -10), new Vec3(10, 0, 10), WHITE, "floor");
    /** The point on the floor that the first tests shade, and the light 10 above it. */
    static final Vec3 X = new Vec3(0, 0, 0);
    static final PointLight LIGHT = light(0, 10, 0);

    static PointLight light(double x, double y, double z) {
        return new PointLight(new Vec3(x, y, z), new Color(1, 1, 1), true, "light");
    }

    static Sphere ball(double x, double y, double z, double r) {
        return new Sphere(new Vec3(x, y, z), r, WHITE, "ball at (" + x + ", " + y + ", " + z + ")");
    }

    static Surface scene(Surface... surfaces) {
        return new Group(List.of(surfaces), "scene");
    }

    @Test
    @DisplayName("a ball between the point and the light casts a shadow (scratch names it)")
    void blockerBetween() {
        Sphere ball = ball(0, 5, 0, 1);
        Check.shadowed(scene(FLOOR, ball), X, UP, LIGHT, ball,
                "the shadow ray r(t) = x + t·(light − x) meets the ball at t = 0.4");
    }

    @Test
    @DisplayName("a ball just below the light still casts a shadow")
    void blockerNearTheLight() {
        // Light at y = 6.5, ball top at y = 6: the ray meets the ball at t = 4/6.5 < 1.
        Sphere ball = ball(0, 5, 0, 1);
        Check.shadowed(scene(FLOOR, ball), X, UP, light(0, 6.5, 0), ball, null);
    }

    @Test
    @DisplayName("a small ball 0.001 above the point still casts a shadow (keep the offset tiny)")
    void blockerVeryClose() {
        // Radius 0.01, lowest point at y = 0.001: the shadow ray meets it at t = 0.0001.
        Sphere pebble = new Sphere(new Vec3(0, 0.011, 0), 0.01, WHITE, "pebble");
        Check.shadowed(scene(FLOOR, pebble), X, UP, LIGHT, pebble,
                "move the shadow ray's start by a tiny amount only (say 1e-6), not 0.1");
    }

    @Test
    @DisplayName("a ball beyond the light casts no shadow")
    void blockerBeyondLight() {
        // Ball from y = 14 to 16, light at y = 10: on the shadow ray that is t = 1.4 to 1.6.
        Check.lit(scene(FLOOR, ball(0, 15, 0, 1)), X, UP, LIGHT,
                "only blockers between the point and the light count (t < 1 for d = light − x)");
    }

    @Test
    @DisplayName("a ball behind the point (under the floor) casts no shadow")
    void blockerBehindPoint() {
        // Ball from y = −6 to −4: on the shadow ray that is t = −0.6 to −0.4, behind x.
        Check.lit(scene(FLOOR, ball(0, -5, 0, 1)), X, UP, LIGHT,
                "only blockers in front of the point count (t > 0)");
    }

    @Test
    @DisplayName("a lamp standing on the floor is not blocked by the floor (t = 1 is the light)")
    void lightOnAFloor() {
        // x is the bottom of a ball hovering over the floor; the lamp lies exactly on the floor's
        // top face y = 0, so the shadow ray reaches the floor at t = 1, the light itself.
        Sphere ball = ball(0, 3, 0, 1);
        Check.lit(scene(FLOOR, ball), new Vec3(0, 2, 0), new Vec3(0, -1, 0), light(0.5, 0, 0.5),
                "the light itself is not a blocker: only t < 1 counts, and a Ray's range is closed, so use"
                        + " tMax = Math.nextDown(1.0), the largest double below 1 (or stop a tiny ε short)");
    }

    @Test
    @DisplayName("a point on the floor beside a box is lit from the open side (the floor touches x at t = 0)")
    void besideABox() {
        // The box stands on the floor; x = (0.75, 0, 0) lies on the floor, 0.25 in front of the
        // box's face x = 1, and the light is on the open side. The floor itself touches the shadow
        // ray at t = 0, where it starts: only blockers with t > 0 count. (Exactly on the line
        // where the box meets the floor, a set of measure zero that no render shows, either answer
        // is accepted: no test puts x there.)
        Box block = new Box(new Vec3(1, 0, -1), new Vec3(2, 1, 1), WHITE, "block on the floor");
        Check.lit(scene(FLOOR, block), new Vec3(0.75, 0, 0), UP, light(-3, 4, 0),
                "only blockers strictly after the point count, t > 0: tMin = 0 on a closed range counts the"
                        + " floor x lies on; raise tMin above 0 (for example to Double.MIN_VALUE or ε) or start the"
                        + " ray a small ε off the surface along n");
    }

    @Test
    @DisplayName("a thin card 0.005 above the point casts a shadow (the offset must be tiny)")
    void closeBlocker() {
        // A card from y = 0.004 to 0.006 right above x = (0, 0, 0), the light 10 above: on the
        // shadow ray d = light − x the card is at t = 0.0004 to 0.0006. A shadow ray that starts
        // 0.01 off the surface (or skips t < 0.001) starts beyond it.
        Box card = new Box(new Vec3(-0.5, 0.004, -0.5), new Vec3(0.5, 0.006, 0.5), WHITE, "thin card");
        Check.shadowed(scene(FLOOR, card), X, UP, LIGHT, card,
                "the card is 0.004 above x: an offset ε (or a tMin) that large skips it; keep the offset tiny"
                        + " (Shadows.EPSILON = 1e-6 is enough against acne at everyday sizes)");
    }

    @Test
    @DisplayName("a ball beside the path casts no shadow")
    void blockerBeside() {
        Check.lit(scene(FLOOR, ball(3, 5, 0, 1)), X, UP, LIGHT, null);
    }

    @Test
    @DisplayName("a big blocker at scale 100 casts a shadow")
    void largeScale() {
        Sphere ball = ball(0, 300, 0, 50);
        Check.shadowed(scene(FLOOR, ball), X, UP, light(0, 1000, 0), ball, null);
    }

    @Test
    @DisplayName("the sphere itself hides a light on its far side")
    void lightOnTheFarSide() {
        // x = (1,0,0) on the unit sphere, the light at (−3,0,0): the shadow ray crosses the
        // whole sphere and leaves it at (−1,0,0), t = 0.5.
        Sphere s = ball(0, 0, 0, 1);
        Check.shadowed(scene(s), new Vec3(1, 0, 0), new Vec3(1, 0, 0), light(-3, 0, 0), s,
                "the surface x lies on can block the light too; do not skip it, and keep"
                        + " the offset tiny");
    }

    @ParameterizedTest(name = "scale {0}")
    @ValueSource(doubles = {1, 100})
    @DisplayName("a sphere does not shadow its own lit side (points found by tracing rays)")
    void noAcneOnSphere(double scale) {
        Random rnd = new Random(7);
        Vec3 c = new Vec3(0.3, -0.2, 0.5).times(scale);
        double r = 1.3 * scale;
        Sphere s = new Sphere(c, r, WHITE, "sphere at scale " + scale);
        Vec3 eye = c.plus(new Vec3(0.4, 0.7, 5).times(scale));
        for (int i = 0; i < 50; i++) {
            // Aim at a random point of the sphere's disc as seen from the eye.
            Vec3 aim = c.plus(randomUnit(rnd).times(0.9 * r * rnd.nextDouble()));
            Vec3 d = aim.minus(eye);
            Vec3 x = firstHit(eye, d, c, r);
            Vec3 n = x.minus(c).normalize();
            // A light well above the surface at x (n·l ≥ 0.5), at about 3 times the radius.
            Vec3 toLight;
            do {
                toLight = n.plus(randomUnit(rnd).times(0.8)).normalize();
            } while (toLight.dot(n) < 0.5);
            PointLight light = new PointLight(x.plus(toLight.times(3 * r)), Color.WHITE, true,
                    "light #" + i);
            Check.lit(scene(s), x, n, light, ACNE);
        }
    }

    @ParameterizedTest(name = "scale {0}")
    @ValueSource(doubles = {1, 100})
    @DisplayName("a floor does not shadow itself from a light above (points found by tracing rays)")
    void noAcneOnFloor(double scale) {
        Random rnd = new Random(11);
        Box floor = new Box(new Vec3(-100, -1, -100).times(scale),
                new Vec3(100, 0, 100).times(scale), WHITE, "floor at scale " + scale);
        Vec3 eye = new Vec3(0.3, 2.7, 5.1).times(scale);
        for (int i = 0; i < 50; i++) {
            Vec3 d = new Vec3(rnd.nextDouble() * 2 - 1, -0.2 - rnd.nextDouble(),
                    -rnd.nextDouble() * 2);
            // Where the ray meets the plane y = 0: t = −p_y / d_y. Rounding leaves x.y a
            // hair above or below 0, as in a real render.
            double t = -eye.y / d.y;
            Vec3 x = eye.plus(d.times(t));
            PointLight light = new PointLight(x.plus(new Vec3(rnd.nextDouble() - 0.5, 3,
                    rnd.nextDouble() - 0.5).times(scale)), Color.WHITE, true, "light #" + i);
            Check.lit(scene(floor), x, UP, light, ACNE);
        }
    }

    /** Where p + t·d first meets the sphere (c, r): the quadratic formula, nearer root. */
    static Vec3 firstHit(Vec3 p, Vec3 d, Vec3 c, double r) {
        Vec3 f = p.minus(c);
        double a = d.dot(d);
        double b = f.dot(d);
        double t = (-b - Math.sqrt(b * b - a * (f.dot(f) - r * r))) / a;
        return p.plus(d.times(t));
    }

    static Vec3 randomUnit(Random rnd) {
        return new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalize();
    }
}
