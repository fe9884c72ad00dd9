package raylab.numerics;

import raylab.light.PointLight;
import raylab.math.Numerics;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.shading.Shadows;
import raylab.surface.Surface;

/**
 * Ways to start a shadow ray, all with the signature of {@link Shadows#isShadowed}: the shadow
 * ray runs from (a point near) x to the light, t in [0, 1]. The offsets the reference used
 * before its local one are the study's own ({@code raylab.study.EarlierOffsets}).
 */
public final class ShadowOffsets {
    private ShadowOffsets() {
    }

    /** The signature of {@link Shadows#isShadowed}. */
    @FunctionalInterface
    public interface ShadowTest {
        boolean isShadowed(Surface scene, Vec3 x, Vec3 n, PointLight light,
                IntersectionRecord scratch);
    }

    /** No offset at all: the shadow ray starts exactly at the computed hit point. */
    public static boolean none(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        Ray shadowRay = new Ray(x, light.position.minus(x), Double.MIN_VALUE, Math.nextDown(1.0));
        return scene.intersectsAny(shadowRay, scratch);
    }

    /**
     * The common fix: move the origin a fixed distance {@link Shadows#EPSILON} (10⁻⁶ scene
     * units) along the normal, toward the light's side. Too small for large or far-from-origin
     * scenes (acne), too large for tiny ones (light leaks past thin blockers).
     */
    public static boolean fixedEpsilon(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        Vec3 toLight = light.position.minus(x);
        Vec3 offset = n.times(n.dot(toLight) >= 0 ? Shadows.EPSILON : -Shadows.EPSILON);
        Vec3 origin = x.plus(offset);
        Ray shadowRay = new Ray(origin, light.position.minus(origin), Double.MIN_VALUE, Math.nextDown(1.0));
        return scene.intersectsAny(shadowRay, scratch);
    }

    /**
     * The reference, {@link Shadows#isShadowed}: the local offset, from the error bound of the
     * hit point ({@link Numerics#pointError}), widened to the bound of the surface the shadow ray
     * meets when it meets one within that surface's own rounding error of x.
     */
    public static boolean localOffset(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        return Shadows.isShadowed(scene, x, n, light, scratch);
    }
}
