// Mistake corpus (NoSilentLossTest): n·l instead of n·h.
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
    @Override
    public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
        Vec3 h = v.plus(l).times(0.5); // BUG: halved, not normalized: a unit vector only when v = l
        return ks.times(I).times(Math.pow(Math.max(0.0, n.dot(h)), p));
    }
}
