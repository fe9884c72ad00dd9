package raylab.material;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.testing.Check;

/** Milestone phong: {@link BlinnPhong#specular}. Run with {@code ./mvnw test -Dgroups=phong}. */
@Tag("phong")
class BlinnPhongTest {
    static final Vec3 N = new Vec3(0, 0, 1);
    static final Color WHITE_LIGHT = new Color(1, 1, 1);

    static BlinnPhong shiny(Color ks, double p) {
        return new BlinnPhong(new Color(0.5, 0.5, 0.5), ks, p, Color.BLACK, "shiny");
    }

    static Color grey(double s) {
        return new Color(s, s, s);
    }

    @ParameterizedTest(name = "p = {0}")
    @CsvSource({"1", "10", "100"})
    @DisplayName("mirror configuration: h = n, so L_s = ks·I whatever p")
    void mirror(double p) {
        // l and v at 30° on either side of n:
        // l = (sin 30°, 0, cos 30°), v = (−sin 30°, 0, cos 30°).
        // v + l = (0, 0, 2 cos 30°), so h = (0,0,1) = n and n·h = 1.
        // ks∘I = (0.5·1, 0.5·0.8, 0.5·0.6) = (0.5, 0.4, 0.3).
        Vec3 l = new Vec3(0.5, 0, Math.sqrt(3) / 2);
        Vec3 v = new Vec3(-0.5, 0, Math.sqrt(3) / 2);
        Color got = shiny(grey(0.5), p).specular(N, l, v, new Color(1, 0.8, 0.6));
        Check.color("specular in the mirror configuration, p = " + p, new Color(0.5, 0.4, 0.3),
                got, "h = (v + l)/‖v + l‖ is n here, so n·h = 1");
    }

    @ParameterizedTest(name = "p = {0}: n·h^p = {1}")
    @CsvSource({
        "1,   0.7071067811865476",     // 1/√2
        "10,  0.03125",                 // (1/√2)^10 = 1/2^5
        "100, 8.881784197001252e-16"})  // (1/√2)^100 = 1/2^50
    @DisplayName("v = n, l along the surface: h at 45°, n·h = 1/√2")
    void fortyFiveDegrees(double p, double expected) {
        // v = (0,0,1), l = (1,0,0): v + l = (1,0,1), h = (1,0,1)/√2, n·h = 1/√2.
        Color got = shiny(grey(1), p).specular(N, new Vec3(1, 0, 0), N, WHITE_LIGHT);
        // n·l = 0 here, and so is the reflection vector's r·v (v = n): black names both mistakes.
        Check.colorLikely("specular with n·h = 1/√2, p = " + p, grey(expected), got,
                new Check.Likely(Color.BLACK, "black: the term must use n·h with the half vector h = (v + l)/‖v + l‖"
                        + " (n·h = 1/√2 here); n·l and the reflection vector's r·v are both 0 here"));
    }

    @Test
    @DisplayName("v off the normal: the half vector's n·h, not n·l or the reflection vector's r·v")
    void halfVectorNotReflection() {
        // n = (0,0,1), l = (0.6,0,0.8), v = (0,0.28,0.96): v + l = (0.6,0.28,1.76), n·h = 1.76/√3.536.
        // Wrong forms give other values, no two alike: n·l = 0.8; r = 2(n·l)n − l = (−0.6,0,0.8),
        // r·v = 0.768; n·(v + l) = 1.76; n·(v + l)/2 = 0.88 (with v and l at the same height above
        // the surface, (v + l)/2 would give n·l exactly: a hint could not tell them apart).
        Vec3 l = new Vec3(0.6, 0, 0.8);
        Vec3 v = new Vec3(0, 0.28, 0.96);
        double p = 4;
        double nh = 1.76 / Math.sqrt(3.536);
        Color got = shiny(grey(1), p).specular(N, l, v, WHITE_LIGHT);
        Check.colorLikely("specular with n·h = 1.76/√3.536, p = 4", grey(Math.pow(nh, p)), got,
                new Check.Likely(grey(Math.pow(0.8, p)), "that is max(0, n·l)^p: the highlight uses n·h with the half"
                        + " vector h = (v + l)/‖v + l‖, not n·l"),
                new Check.Likely(grey(Math.pow(0.768, p)), "that is Phong's reflection-vector term max(0, r·v)^p with"
                        + " r = 2(n·l)n − l; Blinn-Phong uses the half vector instead: max(0, n·h)^p, h = (v + l)/‖v + l‖"),
                new Check.Likely(grey(Math.pow(1.76, p)), "n·(v + l) without dividing by ‖v + l‖: h must be a unit"
                        + " vector"),
                new Check.Likely(grey(Math.pow(0.88, p)), "n·(v + l)/2: halving v + l does not make it a unit vector"
                        + " (only when v and l are the same vector); divide by its length ‖v + l‖"));
    }

    @ParameterizedTest(name = "p = {0}: n·h^p = {1}")
    @CsvSource({
        "1,   0.9486832980505138",     // 3/√10
        "2,   0.9",                     // (3/√10)² = 9/10
        "10,  0.59049",                 // 0.9^5
        "100, 0.005153775207320113"})  // 0.9^50
    @DisplayName("v = n, l at cos = 0.8: n·h = 3/√10")
    void knownAngle(double p, double expected) {
        // v = (0,0,1), l = (0.6,0,0.8): v + l = (0.6, 0, 1.8) = 0.6·(1,0,3), so h = (1,0,3)/√10
        // and n·h = 3/√10; (n·h)² = 9/10.
        Color got = shiny(grey(1), p).specular(N, new Vec3(0.6, 0, 0.8), N, WHITE_LIGHT);
        Check.colorLikely("specular with n·h = 3/√10, p = " + p, grey(expected), got,
                new Check.Likely(grey(Math.pow(1.8, p)), "n·(v + l) = 1.8 here: h = (v + l)/‖v + l‖ must be a unit vector;"
                        + " L_s = ks∘I·max(0, n·h)^p"),
                new Check.Likely(grey(Math.pow(0.8, p)), "0.8 = n·l here (and the reflection vector's r·v, since v = n):"
                        + " the highlight uses n·h with the half vector h = (v + l)/‖v + l‖ (n·h = 3/√10)"));
    }

    @Test
    @DisplayName("ks and I are multiplied channel by channel")
    void perChannel() {
        // Mirror configuration (n·h = 1): ks∘I = (1·0.2, 0.5·0.4, 0·1) = (0.2, 0.2, 0).
        Color got = shiny(new Color(1, 0.5, 0), 20).specular(N, N, N, new Color(0.2, 0.4, 1));
        Check.color("specular with ks = (1,0.5,0), I = (0.2,0.4,1)", new Color(0.2, 0.2, 0), got,
                "multiply per channel: ks.times(I)");
    }

    @Test
    @DisplayName("swapping v and l gives the same highlight")
    void symmetric() {
        Vec3 a = new Vec3(0.6, 0, 0.8);
        BlinnPhong m = shiny(grey(1), 10);
        Check.color("specular with v and l swapped", m.specular(N, a, N, WHITE_LIGHT),
                m.specular(N, N, a, WHITE_LIGHT), "h = (v + l)/‖v + l‖ treats v and l alike");
        Check.specularControl();
    }

    @ParameterizedTest(name = "p = {0}")
    @CsvSource({"1", "10"})
    @DisplayName("n·h ≤ 0: no highlight (black, not negative or positive)")
    void halfVectorBelow(double p) {
        // v = (0,0,−1), l = (1,0,0): h = (1,0,−1)/√2, so n·h = −1/√2 < 0. Without the clamp,
        // p = 1 gives a negative value and p = 10 a positive one (−1/√2)^10 = 1/32.
        Color got = shiny(grey(1), p).specular(N, new Vec3(1, 0, 0), new Vec3(0, 0, -1),
                WHITE_LIGHT);
        Check.color("specular with n·h = −1/√2, p = " + p, Color.BLACK, got,
                "clamp before the power: max(0, n·h)^p (an even p turns a negative n·h positive)");
        Check.specularControl();
    }

    @Test
    @DisplayName("black ks: no highlight at all")
    void blackKs() {
        Color got = shiny(Color.BLACK, 10).specular(N, N, N, WHITE_LIGHT);
        Check.color("specular with ks = 0", Color.BLACK, got, null);
        Check.specularControl();
    }

    @Test
    @DisplayName("a larger p gives a smaller highlight away from the mirror direction")
    void sharperWithLargerP() {
        // n·h = 3/√10 < 1 (as in knownAngle): 0.9^5 = 0.59049 for p = 10, 0.9^25 for p = 50.
        Vec3 l = new Vec3(0.6, 0, 0.8);
        Color p10 = shiny(grey(1), 10).specular(N, l, N, WHITE_LIGHT);
        Color p50 = shiny(grey(1), 50).specular(N, l, N, WHITE_LIGHT);
        Check.color("specular p = 10", grey(0.59049), p10, null);
        Check.color("specular p = 50", grey(Math.pow(0.9, 25)), p50, null);
    }
}
