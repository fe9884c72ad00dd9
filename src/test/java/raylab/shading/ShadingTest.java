package raylab.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.testing.Check;

/**
 * Milestone lambert: the lecture's shade() loop, {@link Shading#shade}. Run with
 * {@code ./mvnw test -Dgroups=lambert}.
 *
 * <p>Set-up: x = (0, 0, 0) on a floor with n = (0, 1, 0), viewer straight above (v = n) but in one
 * check (a grazing viewer, where v·l and n·l differ in sign). A light
 * at (0, 2, 0) has l = n, n·l = 1; one at (3, 4, 0) has l = (0.6, 0.8, 0), n·l = 0.8; one at
 * (0, −2, 0) is below the floor, n·l = −1.
 */
@Tag("lambert")
class ShadingTest {
    static final Vec3 X = Vec3.ZERO;
    static final Vec3 N = new Vec3(0, 1, 0);
    static final Color KD = new Color(0.5, 0.4, 0.2);
    static final Color KA = new Color(0.2, 0.3, 0.4);
    static final Color IA = new Color(0.5, 0.5, 1);
    static final Lambertian MATTE = new Lambertian(KD, KA, "matte");
    static final Color I1 = new Color(1, 0.5, 0.25);
    static final Color I2 = new Color(0.5, 1, 1);
    static final PointLight ABOVE = new PointLight(new Vec3(0, 2, 0), I1, true, "above");
    static final PointLight SIDE = new PointLight(new Vec3(3, 4, 0), I2, true, "side");
    static final PointLight BELOW = new PointLight(new Vec3(0, -2, 0), I1, true, "below the floor");

    /** The point, with "visible" answered from the set of blocked lights, recording every question. */
    static ShadingPoint at(Lambertian m, Set<PointLight> blocked, List<String> asked) {
        return ShadingPoint.plain(X, N, N, m, IA, light -> {
            asked.add(light.name);
            return !blocked.contains(light);
        });
    }

    static Color shade(Lambertian m, Set<PointLight> blocked, List<String> asked, PointLight... lights) {
        return Shading.shade(at(m, blocked, asked), List.of(lights));
    }

    @Test
    @DisplayName("no lights: only the ambient term ka·Ia")
    void ambientOnly() {
        Check.color("shade() without lights", KA.times(IA), shade(MATTE, Set.of(), new ArrayList<>()),
                "result starts as the ambient term at.ambient() (ka·Ia)");
    }

    @Test
    @DisplayName("one light above: ka·Ia + kd·I·(n·l)")
    void oneLight() {
        Check.color("shade() with one light above, n·l = 1", KA.times(IA).plus(KD.times(I1)),
                shade(MATTE, Set.of(), new ArrayList<>(), ABOVE),
                "add at.diffuse(light, l) with l = at.toLight(light), the unit direction to the light");
    }

    @Test
    @DisplayName("two lights add up, the ambient term is added once")
    void twoLightsAdd() {
        Color expected = KA.times(IA).plus(KD.times(I1)).plus(KD.times(I2).times(0.8));
        Check.color("shade() with lights above (n·l = 1) and at the side (n·l = 0.8)", expected,
                shade(MATTE, Set.of(), new ArrayList<>(), ABOVE, SIDE),
                "loop over all lights and add each one's terms; ka·Ia once, before the loop");
    }

    @Test
    @DisplayName("a light in shadow adds nothing (and the ambient term stays)")
    void blockedLight() {
        // The skip hint only when the blocked light's own term came back: code that skips it
        // and errs elsewhere (the ambient term per light) is not told to skip it.
        String skip = "skip a light when at.visible(light) is false";
        Color expected = KA.times(IA).plus(KD.times(I2).times(0.8));
        Check.colorLikely("shade() with the light above blocked", expected,
                shade(MATTE, Set.of(ABOVE), new ArrayList<>(), ABOVE, SIDE),
                new Check.Likely(expected.plus(KD.times(I1)), skip + ": the blocked light's diffuse term was added"));
        Check.colorLikely("shade() with every light blocked", KA.times(IA),
                shade(MATTE, Set.of(ABOVE, SIDE), new ArrayList<>(), ABOVE, SIDE),
                new Check.Likely(KA.times(IA).plus(KD.times(I1)).plus(KD.times(I2).times(0.8)), skip
                        + ": both blocked lights were added"),
                new Check.Likely(KA.times(IA).times(2), "the ambient term is added once, before the loop, whatever the"
                        + " lights"));
        // A glossy material: a blocked light adds no highlight either (the whole light is skipped).
        Color glossy = expected.plus(Glossy.KS.times(I2));
        Check.colorLikely("shade() of a material with a specular term, the light above blocked", glossy,
                shade(new Glossy(), Set.of(ABOVE), new ArrayList<>(), ABOVE, SIDE),
                new Check.Likely(glossy.plus(Glossy.KS.times(I1)), "the blocked light still added its specular term:"
                        + " a light in shadow adds no highlight either; skip the whole light (diffuse and specular)"
                        + " when at.visible(light) is false"),
                new Check.Likely(glossy.plus(Glossy.KS.times(I1)).plus(KD.times(I1)), skip
                        + ": the blocked light's diffuse and specular terms were added"));
    }

    @Test
    @DisplayName("a light behind the surface adds nothing")
    void lightBehind() {
        List<String> asked = new ArrayList<>();
        Check.color("shade() with a light below the floor", KA.times(IA).plus(KD.times(I1)),
                shade(MATTE, Set.of(), asked, BELOW, ABOVE), "skip lights with n·l <= 0");
        // The other way round: in front is the normal's side, not the viewer's. The viewer at a
        // grazing v = (0.8, 0.6, 0), a light at (−4, 3, 0): l = (−0.8, 0.6, 0), n·l = 0.6 > 0 but
        // v·l = −0.28.
        PointLight across = new PointLight(new Vec3(-4, 3, 0), I1, true, "across from the viewer");
        Check.color("shade() with the viewer at v = (0.8, 0.6, 0) and a light at (−4, 3, 0), n·l = 0.6",
                KA.times(IA).plus(KD.times(I1).times(0.6)),
                Shading.shade(ShadingPoint.plain(X, N, new Vec3(0.8, 0.6, 0), MATTE, IA, light -> true), List.of(across)),
                "a light is in front when n·l > 0, on the normal's side, wherever the viewer v is");
        // Asking at.visible for the light below is a cost (a shadow ray), not a wrong result:
        // a zero-point note, never a failure.
        Check.skippableShadowRays((int) asked.stream().filter(n -> n.equals("below the floor")).count());
    }

    /**
     * A matte material with a stand-in specular term ks·I whatever the angles (the real
     * Blinn-Phong term is milestone phong): it shows whether, and how often, shade() adds it.
     */
    static final class Glossy extends Lambertian {
        static final Color KS = new Color(0.03, 0.02, 0.01);

        Glossy() {
            super(KD, KA, "glossy");
        }

        @Override
        public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
            return KS.times(I);
        }
    }

    @Test
    @DisplayName("a light behind the surface gives no highlight either")
    void noHighlightFromBehind() {
        Color c = shade(new Glossy(), Set.of(), new ArrayList<>(), BELOW);
        Check.color("shade() of a material with a specular term, light below the floor (n·l < 0)", KA.times(IA), c,
                "a light with n·l <= 0 adds no term at all: skip it before adding diffuse and specular");
        // On the horizon, n·l = 0 exactly: not in front either (Blinn-Phong's n·h is still 0.71 there).
        PointLight horizon = new PointLight(new Vec3(3, 0, 0), I1, true, "on the horizon");
        Check.color("shade() of a material with a specular term, light on the horizon (n·l = 0)", KA.times(IA),
                shade(new Glossy(), Set.of(), new ArrayList<>(), horizon),
                "in front means n·l > 0: a light with n·l = 0 adds no highlight either");
    }

    @Test
    @DisplayName("each visible light adds its diffuse and its specular term")
    void specularAdded() {
        Color expected = KA.times(IA).plus(KD.times(I1)).plus(Glossy.KS.times(I1))
                .plus(KD.times(I2).times(0.8)).plus(Glossy.KS.times(I2));
        Check.color("shade() of a material with a specular term, lights above and at the side", expected,
                shade(new Glossy(), Set.of(), new ArrayList<>(), ABOVE, SIDE),
                "the shading contribution is at.diffuse(light, l) plus at.specular(light, l)");
    }

    @Test
    @DisplayName("a light exactly at the point adds nothing, and no NaN")
    void lightAtThePoint() {
        PointLight atX = new PointLight(X, I1, true, "at x");
        List<String> asked = new ArrayList<>();
        Color c = shade(MATTE, Set.of(), asked, atX);
        assertTrue(c.isFinite(), "NaN or infinite radiance for a light exactly at x: " + c);
        Check.color("shade() with a light exactly at x", KA.times(IA), c,
                "at.toLight(light) is (0, 0, 0) there, so n·l = 0: the light is not in front");
        Check.color("shade() of a material with a specular term, a light exactly at x", KA.times(IA),
                shade(new Glossy(), Set.of(), asked, atX),
                "at.toLight(light) is (0, 0, 0) there, so n·l = 0: the light is not in front, and adds no highlight");
        Check.skippableShadowRays(asked.size());
    }
}
