package raylab.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static raylab.hidden.Hidden.uniform;
import static raylab.hidden.Hidden.unit;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.hidden.Hidden;
import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.testing.Check;

/** Hidden tests of Shading.shade (grader only): the lecture's loop on seeded random points and lights. */
@Tag("lambert")
class ShadingHiddenTest {
    /** Blinn-Phong written out here, so these tests need only milestone lambert. */
    static final class Shiny extends Lambertian {
        final Color ks;
        final double p;

        Shiny(Color kd, Color ks, double p, Color ka) {
            super(kd, ka, "shiny");
            this.ks = ks;
            this.p = p;
        }

        @Override
        public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
            Vec3 h = v.plus(l);
            h = h.times(1 / h.length());
            return ks.times(I).times(Math.pow(Math.max(0, n.dot(h)), p));
        }
    }

    private static Color color(SplittableRandom r, double lo, double hi) {
        return new Color(uniform(r, lo, hi), uniform(r, lo, hi), uniform(r, lo, hi));
    }

    /** The sum written out independently: ka·Ia + Σ over lights in front and visible of kd I n·l + ks I (n·h)^p. */
    private static Color expected(Vec3 x, Vec3 n, Vec3 v, Shiny m, Color ia, List<PointLight> lights,
            Set<PointLight> blocked) {
        double[] sum = {m.ka.r * ia.r, m.ka.g * ia.g, m.ka.b * ia.b};
        for (PointLight light : lights) {
            Vec3 d = light.position.minus(x);
            double len = d.length();
            if (len == 0) {
                continue;
            }
            Vec3 l = d.times(1 / len);
            double nl = n.dot(l);
            if (nl <= 0 || blocked.contains(light)) {
                continue;
            }
            Vec3 h = v.plus(l);
            h = h.times(1 / h.length());
            double s = Math.pow(Math.max(0, n.dot(h)), m.p);
            Color I = light.intensity;
            sum[0] += m.kd.r * I.r * nl + m.ks.r * I.r * s;
            sum[1] += m.kd.g * I.g * nl + m.ks.g * I.g * s;
            sum[2] += m.kd.b * I.b * nl + m.ks.b * I.b * s;
        }
        return new Color(sum[0], sum[1], sum[2]);
    }

    @Test
    @DisplayName("random points, lights and blockers: L = ka·Ia + Σ over visible lights of kd·I·max(0, n·l) + ks·I·max(0, n·h)^p")
    void randomPointsLightsAndShadowsSumLikeTheLecture() {
        long seed = 0x5ad1L;
        SplittableRandom r = Hidden.rng(seed);
        int skippable = 0;
        for (int i = 0; i < 300; i++) {
            Vec3 x = Hidden.point(r, 20);
            Vec3 n = unit(r);
            Vec3 v = Hidden.within(r, n, 0.05);
            Shiny m = new Shiny(color(r, 0, 1), i % 3 == 0 ? Color.BLACK : color(r, 0, 1), uniform(r, 1, 100),
                    color(r, 0, 1));
            Color ia = i % 4 == 0 ? Color.BLACK : color(r, 0, 0.5);
            List<PointLight> lights = new ArrayList<>();
            Set<PointLight> blocked = new HashSet<>();
            int k = r.nextInt(5);
            for (int j = 0; j < k; j++) {
                PointLight light = new PointLight(x.plus(unit(r).times(uniform(r, 0.5, 30))), color(r, 0, 1.5), true,
                        "light " + j);
                lights.add(light);
                if (r.nextInt(3) == 0) {
                    blocked.add(light);
                }
            }
            List<String> asked = new ArrayList<>();
            ShadingPoint at = ShadingPoint.plain(x, n, v, m, ia, light -> {
                asked.add(light.name);
                return !blocked.contains(light);
            });
            Color got = Shading.shade(at, lights);
            String ctx = " #" + i + " (seed " + seed + "): x " + x + ", n " + n + ", " + lights.size() + " light(s), blocked "
                    + blocked.stream().map(l -> l.name).sorted().toList();
            Hidden.assertColor("shade()" + ctx, expected(x, n, v, m, ia, lights, blocked), got,
                    "result = ka·Ia once; for each light with n·l > 0 that is visible, add diffuse + specular");
            // Shadow rays toward lights behind the surface are a cost, not a wrong result: a note.
            List<String> behind = lights.stream().filter(l -> !(n.dot(l.position.minus(x)) > 0)).map(l -> l.name).toList();
            skippable += (int) asked.stream().filter(behind::contains).count();
        }
        Check.skippableShadowRays(skippable);
    }

    @Test
    @DisplayName("lights exactly at the point or on the horizon add nothing")
    void lightsExactlyAtThePointOrOnTheHorizonAddNothing() {
        Lambertian m = new Lambertian(new Color(0.5, 0.5, 0.5), new Color(0.1, 0.2, 0.3), "m");
        Vec3 x = new Vec3(1, 2, 3);
        Vec3 n = new Vec3(0, 0, 1);
        PointLight atX = new PointLight(x, Color.WHITE, true, "at x");
        PointLight horizon = new PointLight(x.plus(new Vec3(5, 0, 0)), Color.WHITE, true, "at the horizon line");
        List<String> asked = new ArrayList<>();
        Color c = Shading.shade(ShadingPoint.plain(x, n, n, m, Color.WHITE, l -> asked.add(l.name)),
                List.of(atX, horizon));
        assertTrue(c.isFinite(), "a light exactly at x must not give NaN: " + c);
        Hidden.assertColor("shade() with a light at x and one on the horizon (n·l = 0)", new Color(0.1, 0.2, 0.3), c,
                "only lights with n·l > 0 count; toLight gives (0, 0, 0) for a light at x");
        Check.skippableShadowRays(asked.size());
    }
}
