package raylab.material;

import static raylab.hidden.Hidden.assertColor;
import static raylab.hidden.Hidden.uniform;
import static raylab.hidden.Hidden.unit;

import java.util.SplittableRandom;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.hidden.Hidden;
import raylab.math.Color;
import raylab.math.Vec3;

/**
 * Hidden test of BlinnPhong.specular's clamp (grader only): L_s = ks ∘ I · max(0, n·h)^p for every
 * unit n, l, v, also when the half vector points below the surface (n·h &lt; 0). n faces the viewer
 * (n·v &gt; 0) as the method's contract says; the light is behind the surface. The clamp comes
 * before the power: max(0, (n·h)^p) is positive for an even p and NaN for a fractional p there.
 * The framework's shader never calls specular with n·h &lt; 0 (it skips lights with n·l ≤ 0, and
 * then n·h = (n·l + n·v)/‖l + v‖ &gt; 0), so no render can show this; the method's contract does.
 */
@Tag("phong")
class SpecularClampHiddenTest {
    private static final double[] EXPONENTS = {2, 4, 10, 64, 100, 0.5, 1.5, 2.5, 7.25, 33.3};

    @Test
    @DisplayName("n·h < 0: no highlight, whatever the exponent p")
    void halfVectorBelowTheSurfaceGivesNoHighlightForAnyExponent() {
        long seed = 0xc1a3bL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 200; i++) {
            Vec3 n = unit(r);
            Vec3 v;
            do {
                v = unit(r);
            } while (n.dot(v) < 0.05 || n.dot(v) > 0.6);
            Vec3 l;
            do {
                l = unit(r);
            } while (n.dot(l) > -n.dot(v) - 0.2);
            double p = EXPONENTS[i % EXPONENTS.length];
            Color ks = new Color(uniform(r, 0.1, 1), uniform(r, 0.1, 1), uniform(r, 0.1, 1));
            Color light = new Color(uniform(r, 0.1, 2), uniform(r, 0.1, 2), uniform(r, 0.1, 2));
            BlinnPhong m = new BlinnPhong(new Color(0.5, 0.5, 0.5), ks, p, Color.BLACK, "shiny");
            Vec3 h = v.plus(l).normalize();
            assertColor("Blinn-Phong term at n·h = " + n.dot(h) + " < 0, p = " + p + " #" + i + " (seed " + seed + "): n " + n
                    + ", l " + l + ", v " + v, Color.BLACK, m.specular(n, l, v, light),
                    "clamp before the power: max(0, n·h)^p; (n·h)^p is positive for an even p and NaN for a"
                            + " fractional p when n·h < 0");
        }
        raylab.testing.Check.specularControl();
    }
}
