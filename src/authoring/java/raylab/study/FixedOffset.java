package raylab.study;

import raylab.light.PointLight;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * A shadow test with a fixed offset of any size. raylab.numerics.ShadowOffsets.fixedEpsilon has
 * the one size the framework documents (Shadows.EPSILON = 10⁻⁶); the study also tries a smaller
 * and a larger one, the same way: move the origin ε along the normal, toward the light's side.
 */
final class FixedOffset {
    private FixedOffset() {
    }

    static boolean isShadowed(double epsilon, Surface scene, Vec3 x, Vec3 n, PointLight light, IntersectionRecord scratch) {
        Vec3 toLight = light.position.minus(x);
        Vec3 origin = x.plus(n.times(n.dot(toLight) >= 0 ? epsilon : -epsilon));
        Ray shadowRay = new Ray(origin, light.position.minus(origin), Double.MIN_VALUE, Math.nextDown(1.0));
        return scene.intersectsAny(shadowRay, scratch);
    }
}
