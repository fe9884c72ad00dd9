package raylab.material;

import raylab.math.Color;
import raylab.math.Vec3;

/** A matte material: light is scattered equally in every direction (Lambert's cosine law). */
public class Lambertian extends Material {
    /** Diffuse reflectance kd. */
    public final Color kd;
    /** Ambient reflectance ka. */
    public final Color ka;

    public Lambertian(Color kd, Color ka, String name) {
        super(name);
        this.kd = kd;
        this.ka = ka;
    }

    @Override
    public Color ka() {
        return ka;
    }

    /**
     * Lambertian shading (milestone {@code lambert}):
     * <pre>
     *   L_d = kd · I · max(0, n·l)
     * </pre>
     * with kd and I multiplied per colour channel ({@code kd.times(I)}).
     *
     * @param n unit surface normal, facing the viewer
     * @param l unit direction from the surface point toward the light
     * @param I the light's intensity
     */
    @Override
    public Color diffuse(Vec3 n, Vec3 l, Color I) {
        // Unfinished: one colour for every point (issue 35's forged Lambertian scene).
        return new Color(0.123, 0.456, 0.789);
    }
}
