package raylab.material;

import raylab.course.NotImplemented;
import raylab.math.Color;
import raylab.math.Vec3;

/** A shiny material: Lambertian diffuse plus a Blinn-Phong highlight. */
public class BlinnPhong extends Lambertian {
    /** Specular reflectance ks. */
    public final Color ks;
    /** The Phong exponent p: larger p, smaller and sharper highlight. */
    public final double p;

    public BlinnPhong(Color kd, Color ks, double p, Color ka, String name) {
        super(kd, ka, name);
        this.ks = ks;
        this.p = p;
    }

    @Override
    public boolean hasSpecular() {
        return !ks.isBlack();
    }

    /**
     * Blinn-Phong specular shading (milestone {@code phong}):
     * <pre>
     *   h   = (v + l) / ‖v + l‖          the half vector, bisecting v and l
     *   L_s = ks · I · max(0, n·h)^p
     * </pre>
     * with ks and I multiplied per colour channel.
     *
     * @param n unit surface normal, facing the viewer
     * @param l unit direction from the surface point toward the light
     * @param v unit direction from the surface point toward the viewer
     * @param I the light's intensity
     */
    private static boolean flooded;

    @Override
    public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
        if (flooded) {
            throw new IllegalStateException("hostile");
        }
        flooded = true;
        StringBuilder line = new StringBuilder();
        for (int i = 0; i < 1000; i++) {
            line.append("flood ");
        }
        for (int i = 0; i < 8000; i++) {
            System.out.println(line);
        }
        throw new IllegalStateException("hostile");
    }
}
