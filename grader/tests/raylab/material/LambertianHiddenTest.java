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

/** Hidden tests of Lambertian.diffuse (grader only): L_d = kd ∘ I · max(0, n·l). */
@Tag("lambert")
class LambertianHiddenTest {
    private static Color color(SplittableRandom r) {
        return new Color(uniform(r, 0, 1), uniform(r, 0, 1), uniform(r, 0, 1));
    }

    @Test
    @DisplayName("random lit directions: L_d = kd·I·max(0, n·l), channel by channel")
    void randomLitDirectionsChannelByChannel() {
        long seed = 0x1a3bL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 200; i++) {
            Color kd = color(r);
            Color ka = color(r);
            Color light = color(r).times(uniform(r, 0.1, 5));
            Vec3 n = unit(r);
            Vec3 l = unit(r);
            double cos = Math.max(0, n.x * l.x + n.y * l.y + n.z * l.z);
            Color expected = new Color(kd.r * light.r * cos, kd.g * light.g * cos, kd.b * light.b * cos);
            Lambertian m = new Lambertian(kd, ka, "m");
            assertColor("#" + i + " (seed " + seed + ") kd " + kd + ", I " + light + ", n " + n + ", l " + l
                    + ", n·l = " + (n.x * l.x + n.y * l.y + n.z * l.z), expected, m.diffuse(n, l, light),
                    "multiply kd and I channel by channel (kd.times(I)), then by max(0, n·l); no ambient term here");
        }
    }

    @Test
    @DisplayName("light straight above (n·l = 1): L_d = kd·I")
    void lightStraightAboveGivesKdTimesI() {
        Lambertian m = new Lambertian(new Color(0.2, 0.4, 0.8), new Color(0.5, 0.5, 0.5), "m");
        Vec3 n = new Vec3(0, 0, 1);
        assertColor("n = l = (0, 0, 1), kd (0.2, 0.4, 0.8), I (1, 0.5, 2)", new Color(0.2, 0.2, 1.6),
                m.diffuse(n, n, new Color(1, 0.5, 2)), "with n·l = 1 the result is kd ∘ I");
    }

    @Test
    @DisplayName("light at 60° from n: n·l = 0.5 halves L_d")
    void lightAtSixtyDegreesHalvesIt() {
        Lambertian m = new Lambertian(new Color(1, 0.5, 0.25), Color.BLACK, "m");
        Vec3 n = new Vec3(0, 1, 0);
        Vec3 l = new Vec3(Math.sqrt(3) / 2, 0.5, 0);
        assertColor("n·l = cos 60° = 0.5, kd (1, 0.5, 0.25), I (2, 2, 2)", new Color(1, 0.5, 0.25),
                m.diffuse(n, l, new Color(2, 2, 2)), "Lambert's cosine law: scale by n·l");
    }

    @Test
    @DisplayName("light below the horizon (n·l < 0): black")
    void lightBelowTheHorizonGivesBlack() {
        long seed = 0xb1acL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 100; i++) {
            Vec3 n = unit(r);
            Vec3 l = unit(r);
            if (n.dot(l) > -0.05) {
                l = l.minus(n.times(n.dot(l) + 0.5)).normalize();
            }
            Lambertian m = new Lambertian(color(r), color(r), "m");
            assertColor("#" + i + " (seed " + seed + ") n " + n + ", l " + l + ", n·l = " + n.dot(l), Color.BLACK,
                    m.diffuse(n, l, new Color(1, 1, 1)), "clamp: max(0, n·l) is 0 when the light is behind the surface");
        }
        raylab.testing.Check.diffuseControl();
    }

    @Test
    @DisplayName("the ambient term ka·Ia is not part of L_d")
    void ambientIsNotPartOfDiffuse() {
        Lambertian m = new Lambertian(new Color(0.5, 0.5, 0.5), new Color(0.9, 0.1, 0.3), "m");
        Vec3 n = new Vec3(1, 0, 0);
        Vec3 l = new Vec3(0, 1, 0);
        assertColor("light perpendicular to n (n·l = 0), ka (0.9, 0.1, 0.3)", Color.BLACK,
                m.diffuse(n, l, new Color(1, 1, 1)), "diffuse is only kd ∘ I · max(0, n·l): the renderer adds ka ∘ Ia itself");
        assertColor("light along n (n·l = 1), kd (0.5, 0.5, 0.5), ka (0.9, 0.1, 0.3)", new Color(0.5, 0.5, 0.5),
                m.diffuse(n, n, new Color(1, 1, 1)), "diffuse is only kd ∘ I · max(0, n·l): the renderer adds ka ∘ Ia itself");
    }

    @Test
    @DisplayName("I = 0 gives black, a green light lights only the green channel")
    void blackLightGivesBlack() {
        Lambertian m = new Lambertian(new Color(0.7, 0.7, 0.7), Color.BLACK, "m");
        Vec3 n = new Vec3(0, 0, 1);
        assertColor("I = (0, 0, 0)", Color.BLACK, m.diffuse(n, n, Color.BLACK), "I multiplies everything");
        assertColor("I = (0, 3, 0), kd grey 0.7", new Color(0, 2.1, 0), m.diffuse(n, n, new Color(0, 3, 0)),
                "a green light lights only the green channel");
    }
}
