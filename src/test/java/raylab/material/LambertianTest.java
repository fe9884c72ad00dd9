package raylab.material;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.testing.Check;

/** Milestone lambert: {@link Lambertian#diffuse}. Run with {@code ./mvnw test -Dgroups=lambert}. */
@Tag("lambert")
class LambertianTest {
    static final Vec3 N = new Vec3(0, 0, 1);
    static final Color WHITE_LIGHT = new Color(1, 1, 1);

    static Lambertian matte(double r, double g, double b) {
        return new Lambertian(new Color(r, g, b), Color.BLACK, "matte");
    }

    @Test
    @DisplayName("light straight above (n·l = 1): L_d = kd·I")
    void lightOverhead() {
        Color got = matte(0.5, 0.25, 1).diffuse(N, new Vec3(0, 0, 1), WHITE_LIGHT);
        Check.color("diffuse with n = l = (0,0,1), kd = (0.5,0.25,1), I = (1,1,1)",
                new Color(0.5, 0.25, 1), got, null);
    }

    @Test
    @DisplayName("light at 60° from the normal: n·l = cos 60° = 0.5 halves it")
    void sixtyDegrees() {
        // l = (sin 60°, 0, cos 60°) = (√3/2, 0, 1/2), so n·l = 0.5.
        // kd∘I = (0.8·1, 0.6·2, 0.4·0.5) = (0.8, 1.2, 0.2); times 0.5: (0.4, 0.6, 0.1).
        Vec3 l = new Vec3(Math.sqrt(3) / 2, 0, 0.5);
        Color got = matte(0.8, 0.6, 0.4).diffuse(N, l, new Color(1, 2, 0.5));
        Check.color("diffuse at 60°, kd = (0.8,0.6,0.4), I = (1,2,0.5)", new Color(0.4, 0.6, 0.1),
                got, "L_d = kd∘I·max(0, n·l), channel by channel; here n·l = 0.5");
    }

    @Test
    @DisplayName("light at 45°: n·l = 1/√2")
    void fortyFiveDegrees() {
        // n = (0,1,0), l = (1,1,0)/√2: n·l = 1/√2 ≈ 0.7071; kd = I = 1 in every channel.
        Vec3 l = new Vec3(1, 1, 0).normalize();
        double c = 1 / Math.sqrt(2);
        Color got = matte(1, 1, 1).diffuse(new Vec3(0, 1, 0), l, WHITE_LIGHT);
        Check.color("diffuse at 45°", new Color(c, c, c), got, null);
    }

    @Test
    @DisplayName("a slanted normal: n = (2,3,6)/7, l = (0,0,1), so n·l = 6/7")
    void slantedNormal() {
        Vec3 n = new Vec3(2, 3, 6).times(1 / 7.0);
        Color got = matte(0.7, 0.35, 0.14).diffuse(n, new Vec3(0, 0, 1), WHITE_LIGHT);
        // kd·6/7 = (0.6, 0.3, 0.12)
        Check.color("diffuse with n·l = 6/7", new Color(0.6, 0.3, 0.12), got, null);
    }

    @Test
    @DisplayName("kd and I are multiplied channel by channel")
    void perChannel() {
        // A red light on a cyan-ish surface: kd∘I = (0.2·1, 0.9·0, 0.9·0) = (0.2, 0, 0).
        Color got = matte(0.2, 0.9, 0.9).diffuse(N, N, new Color(1, 0, 0));
        Check.color("diffuse of a red light on kd = (0.2,0.9,0.9)", new Color(0.2, 0, 0), got,
                "multiply per channel: kd.times(I)");
    }

    @Test
    @DisplayName("the light's intensity scales the result (I = 3)")
    void brightLight() {
        Color got = matte(0.5, 0.5, 0.5).diffuse(N, N, new Color(3, 3, 3));
        Check.color("diffuse with I = (3,3,3)", new Color(1.5, 1.5, 1.5), got, null);
    }

    @Test
    @DisplayName("light on the horizon (n·l = 0): black")
    void horizon() {
        Color got = matte(1, 1, 1).diffuse(N, new Vec3(1, 0, 0), WHITE_LIGHT);
        Check.color("diffuse with l ⊥ n", Color.BLACK, got, null);
        Check.diffuseControl();
    }

    @Test
    @DisplayName("light below the surface (n·l < 0): black, not negative")
    void belowHorizon() {
        // n·l = −0.8 for l = (0.6, 0, −0.8).
        Color got = matte(1, 0.5, 0.25).diffuse(N, new Vec3(0.6, 0, -0.8), WHITE_LIGHT);
        Check.color("diffuse with the light below (n·l = −0.8)", Color.BLACK, got,
                "clamp: max(0, n·l), a light below the surface adds nothing");
        got = matte(1, 0.5, 0.25).diffuse(N, new Vec3(0, 0, -1), WHITE_LIGHT);
        Check.color("diffuse with the light straight below (n·l = −1)", Color.BLACK, got,
                "clamp: max(0, n·l), a light below the surface adds nothing");
        Check.diffuseControl();
    }

    @Test
    @DisplayName("black kd reflects nothing")
    void blackSurface() {
        Color got = matte(0, 0, 0).diffuse(N, N, WHITE_LIGHT);
        Check.color("diffuse with kd = 0", Color.BLACK, got, null);
        Check.diffuseControl();
    }

    @Test
    @DisplayName("only the angle between n and l matters: rotating both together changes nothing")
    void onlyTheAngleMatters() {
        // Both at 60° apart, in two different orientations: n·l = 0.5 each time.
        Lambertian m = matte(0.8, 0.6, 0.4);
        Color first = m.diffuse(new Vec3(1, 0, 0), new Vec3(0.5, Math.sqrt(3) / 2, 0), WHITE_LIGHT);
        Color second = m.diffuse(new Vec3(0, -1, 0), new Vec3(0, -0.5, -Math.sqrt(3) / 2),
                WHITE_LIGHT);
        Check.color("diffuse with n = (1,0,0), n·l = 0.5", new Color(0.4, 0.3, 0.2), first, null);
        Check.color("diffuse with n = (0,−1,0), n·l = 0.5", new Color(0.4, 0.3, 0.2), second, null);
    }
}
