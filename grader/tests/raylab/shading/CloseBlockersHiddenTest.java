package raylab.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static raylab.hidden.Hidden.M;
import static raylab.hidden.Hidden.uniform;
import static raylab.hidden.Hidden.unit;
import static raylab.hidden.Hidden.within;

import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.hidden.Hidden;
import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.surface.Box;
import raylab.surface.Group;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Hidden tests of Shadows.isShadowed's contract (grader only): every blocker strictly between the
 * point and the light counts, also one a few thousandths of a unit from either end. Blockers are
 * thin (a small triangle across the shadow ray, hit once), 0.004 to 0.009 units from the point or
 * from the light, which stands 1 to 3 units away: any offset up to 0.001 units (or 0.001 of the
 * distance to the light) passes, and so does the scale-aware one; a fixed 0.01 does not.
 */
@Tag("shadows")
class CloseBlockersHiddenTest {
    /**
     * Asserts that the light is blocked at x, scored with the control that the same point and
     * light in an empty scene are lit ({@link raylab.testing.Check#litControl}).
     */
    private static void assertShadowed(Surface scene, Vec3 x, Vec3 n, PointLight l, IntersectionRecord scratch,
            String message) {
        assertTrue(Shadows.isShadowed(scene, x, n, l, scratch), message);
        raylab.testing.Check.litControl(x, n, l);
    }

    private static final String HINT = "only blockers strictly between x and the light count, but all of them: keep"
            + " the offset (or tMin) tiny, such as 1e-6, or scale it with the coordinates; 0.01 skips nearby blockers";

    /** A small triangle across the line from x toward l, centred on it, at distance s from x. */
    private static Triangle across(Vec3 x, Vec3 l, double s, double size) {
        Vec3 c = x.plus(l.times(s));
        Vec3 a = Math.abs(l.x) < 0.6 ? new Vec3(1, 0, 0) : new Vec3(0, 1, 0);
        Vec3 e1 = l.cross(a).normalize();
        Vec3 e2 = l.cross(e1);
        Vec3 p0 = c.plus(e1.times(size));
        Vec3 p1 = c.plus(e1.times(-0.5 * size)).plus(e2.times(0.866 * size));
        Vec3 p2 = c.plus(e1.times(-0.5 * size)).plus(e2.times(-0.866 * size));
        return new Triangle(p0, p1, p2, M, "blocker");
    }

    private static Surface ground(SplittableRandom r, Vec3[] xn) {
        if (r.nextBoolean()) {
            Sphere s = new Sphere(Hidden.point(r, 15), uniform(r, 1, 10), M, "ground sphere");
            Vec3 u = unit(r);
            xn[0] = s.center.plus(u.times(s.radius));
            xn[1] = u;
            return s;
        }
        Vec3 lo = Hidden.point(r, 15);
        Box b = new Box(lo, lo.plus(new Vec3(uniform(r, 2, 6), uniform(r, 0.5, 2), uniform(r, 2, 6))), M, "ground box");
        xn[0] = new Vec3(uniform(r, lo.x + 0.3, b.max.x - 0.3), b.max.y, uniform(r, lo.z + 0.3, b.max.z - 0.3));
        xn[1] = new Vec3(0, 1, 0);
        return b;
    }

    private static String ctx(int i, long seed, Vec3 x, Vec3 n, Vec3 light, double s, String where) {
        return "#" + i + " (seed " + seed + "): point x " + x + ", normal n " + n + ", light at " + light
                + "; a small triangle crosses the shadow ray " + s + " units " + where + "\n  hint: " + HINT;
    }

    @Test
    @DisplayName("a thin blocker just above the point casts a shadow")
    void aThinBlockerJustAboveThePointCastsAShadow() {
        long seed = 0xc105eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 200; i++) {
            Vec3[] xn = new Vec3[2];
            Surface ground = ground(r, xn);
            Vec3 x = xn[0];
            Vec3 n = xn[1];
            Vec3 l = within(r, n, 0.6);
            double dist = uniform(r, 1, 3);
            double s = uniform(r, 0.004, 0.009);
            // Small enough to stay above the ground: its lowest point is s·(n·l) − size·‖n × l‖ > 0.
            Triangle blocker = across(x, l, s, 0.5 * s * n.dot(l));
            Group scene = new Group(List.of(ground, blocker), "scene");
            PointLight light = new PointLight(x.plus(l.times(dist)), Color.WHITE, true, "light");
            assertShadowed(scene, x, n, light, new IntersectionRecord(),
                    "expected shadowed: " + ctx(i, seed, x, n, light.position, s, "from x"));
        }
    }

    @Test
    @DisplayName("a thin blocker just before the light casts a shadow")
    void aThinBlockerJustBeforeTheLightCastsAShadow() {
        long seed = 0xc10519L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 200; i++) {
            Vec3[] xn = new Vec3[2];
            Surface ground = ground(r, xn);
            Vec3 x = xn[0];
            Vec3 n = xn[1];
            Vec3 l = within(r, n, 0.6);
            double dist = uniform(r, 1, 3);
            double s = uniform(r, 0.004, 0.009);
            Triangle blocker = across(x, l, dist - s, 0.2);
            Group scene = new Group(List.of(ground, blocker), "scene");
            PointLight light = new PointLight(x.plus(l.times(dist)), Color.WHITE, true, "light");
            assertShadowed(scene, x, n, light, new IntersectionRecord(),
                    "expected shadowed: " + ctx(i, seed, x, n, light.position, s, "before the light"));
        }
    }
}
