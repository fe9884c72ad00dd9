package raylab.shading;

import raylab.course.NotImplemented;
import raylab.light.PointLight;
import raylab.math.Numerics;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/** Shadow rays: can a surface point see a light? (milestone {@code shadows}) */
public final class Shadows {
    /** A fixed offset that works for scenes of everyday size (about 1 to 100 units across). */
    public static final double EPSILON = 1e-6;

    private Shadows() {
    }

    /**
     * Whether some surface blocks the light from point x.
     *
     * <p>The shadow ray goes from x toward the light: r(t) = x + t·(light − x), so t = 1 is the
     * light itself. Only blockers strictly between the point and the light count, t in (0, 1).
     * Because x was computed with rounding error it may lie just below the surface, so a ray
     * starting exactly at x can hit the very surface it starts on (shadow acne): start the
     * shadow ray a small distance off the surface, or raise its tMin above 0.
     *
     * @param scene   everything that can block the light; use its cheap any-hit query
     *                {@link Surface#intersectsAny}
     * @param x       the surface point being shaded
     * @param n       unit normal at x, facing the viewer
     * @param light   the light
     * @param scratch a record to pass to {@code intersectsAny}; on return it names the blocker
     * @return true if the light is blocked
     */
    public static boolean isShadowed(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        // Scale-aware offset: 64 to 128 ulps of the largest coordinate of x or of the scene,
        // which bounds the rounding error of any hit point computed in this scene.
        // Unit direction, the light at t = distance; BUG: a large fixed epsilon at both ends.
        double eps = 0.01;
        Vec3 toLight = light.position.minus(x);
        double dist = toLight.length();
        Ray shadowRay = new Ray(x, toLight.times(1 / dist), eps, dist - eps);
        return scene.intersectsAny(shadowRay, scratch);
    }
}
