package raylab.material;

import static raylab.hidden.Hidden.assertColor;
import static raylab.hidden.Hidden.uniform;
import static raylab.hidden.Hidden.unit;
import static raylab.hidden.Hidden.within;

import java.util.SplittableRandom;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.hidden.Hidden;
import raylab.math.Color;
import raylab.math.Vec3;

/**
 * Hidden tests of BlinnPhong.specular (grader only): L_s = ks ∘ I · max(0, n·h)^p with
 * h = (v + l)/‖v + l‖. Only situations the renderer creates are tested: n·l &gt; 0 and n·v &gt; 0.
 */
@Tag("phong")
class BlinnPhongHiddenTest {
    private static Color color(SplittableRandom r) {
        return new Color(uniform(r, 0, 1), uniform(r, 0, 1), uniform(r, 0, 1));
    }

    private static Color expected(Color ks, Color light, Vec3 n, Vec3 l, Vec3 v, double p) {
        double hx = v.x + l.x;
        double hy = v.y + l.y;
        double hz = v.z + l.z;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double nh = (n.x * hx + n.y * hy + n.z * hz) / len;
        double s = Math.pow(Math.max(0, nh), p);
        return new Color(ks.r * light.r * s, ks.g * light.g * s, ks.b * light.b * s);
    }

    @Test
    @DisplayName("random v and l: L_s = ks·I·max(0, n·h)^p")
    void randomViewAndLightDirections() {
        long seed = 0xb11eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 200; i++) {
            Vec3 n = unit(r);
            Vec3 l = within(r, n, 0.05);
            Vec3 v = within(r, n, 0.05);
            Color ks = color(r);
            Color kd = color(r);
            Color light = color(r).times(uniform(r, 0.1, 4));
            double p = Math.pow(2, uniform(r, 0, 9));
            BlinnPhong m = new BlinnPhong(kd, ks, p, Color.BLACK, "m");
            assertColor("#" + i + " (seed " + seed + ") n " + n + ", l " + l + ", v " + v + ", p " + p + ", ks " + ks
                    + ", I " + light, expected(ks, light, n, l, v, p), m.specular(n, l, v, light),
                    "h = normalize(v + l); ks ∘ I · max(0, n·h)^p; no diffuse term in specular");
        }
    }

    @Test
    @DisplayName("mirror direction (h = n): the full highlight ks·I")
    void mirrorDirectionGivesTheFullHighlight() {
        Vec3 n = new Vec3(0, 1, 0);
        Vec3 l = new Vec3(1, 1, 0).normalize();
        Vec3 v = new Vec3(-1, 1, 0).normalize();
        BlinnPhong m = new BlinnPhong(new Color(0.5, 0.5, 0.5), new Color(0.3, 0.6, 0.9), 50, Color.BLACK, "m");
        assertColor("v is l mirrored about n, so h = n; p = 50", new Color(0.6, 1.2, 1.8),
                m.specular(n, l, v, new Color(2, 2, 2)), "n·h = 1 gives ks ∘ I whatever p is");
    }

    @Test
    @DisplayName("h = (v + l) / ‖v + l‖ must be normalized")
    void halfVectorMustBeNormalized() {
        Vec3 n = new Vec3(0, 0, 1);
        Vec3 l = new Vec3(0, 0, 1);
        Vec3 v = new Vec3(0.6, 0, 0.8);
        // v + l = (0.6, 0, 1.8), |v + l| = sqrt(3.6); n·h = 1.8 / sqrt(3.6) = sqrt(0.9).
        double nh = Math.sqrt(0.9);
        BlinnPhong m = new BlinnPhong(Color.BLACK, Color.WHITE, 10, Color.BLACK, "m");
        double s = Math.pow(nh, 10);
        assertColor("l = n, v at 36.87° from n, p = 10: n·h = √0.9", new Color(s, s, s),
                m.specular(n, l, v, Color.WHITE), "divide v + l by its length before the dot product");
    }

    @Test
    @DisplayName("the exponent p sets the size of the highlight")
    void exponentControlsTheHighlightSize() {
        Vec3 n = new Vec3(0, 0, 1);
        Vec3 l = new Vec3(0, Math.sin(0.4), Math.cos(0.4));
        Vec3 v = new Vec3(0, 0, 1);
        // h bisects l and v: the angle between n and h is 0.2 rad.
        double nh = Math.cos(0.2);
        for (double p : new double[] {1, 2.5, 10, 100, 1000}) {
            BlinnPhong m = new BlinnPhong(Color.BLACK, new Color(1, 0.5, 0.25), p, Color.BLACK, "m");
            double s = Math.pow(nh, p);
            assertColor("angle(n, h) = 0.2 rad, p = " + p, new Color(s, 0.5 * s, 0.25 * s),
                    m.specular(n, l, v, Color.WHITE), "raise max(0, n·h) to the power p (Math.pow)");
        }
    }

    @Test
    @DisplayName("L_s uses ks only, not kd or ka")
    void specularIgnoresKdAndKa() {
        Vec3 n = new Vec3(0, 0, 1);
        BlinnPhong m = new BlinnPhong(new Color(0.9, 0.9, 0.9), new Color(0.1, 0.2, 0.3), 8,
                new Color(0.4, 0.4, 0.4), "m");
        assertColor("l = v = n, I = (1, 1, 1)", new Color(0.1, 0.2, 0.3), m.specular(n, n, n, Color.WHITE),
                "specular uses ks only; kd and ka belong to the other terms");
    }

    @Test
    @DisplayName("a coloured light tints the highlight, channel by channel")
    void coloredLightTintsTheHighlight() {
        Vec3 n = new Vec3(0, 0, 1);
        BlinnPhong m = new BlinnPhong(Color.BLACK, new Color(1, 1, 1), 8, Color.BLACK, "m");
        assertColor("l = v = n, I = (0.2, 0, 3)", new Color(0.2, 0, 3), m.specular(n, n, n, new Color(0.2, 0, 3)),
                "multiply ks and I channel by channel");
    }
}
