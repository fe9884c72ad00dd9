package raylab.camera;

import raylab.math.Vec3;
import raylab.ray.Ray;

/**
 * A pinhole camera: all eye rays start at the eye and pass through an image plane at distance 1
 * in front of it, whose height spans the vertical field of view.
 */
public final class PerspectiveCamera extends Camera {
    private final double halfHeight;
    private final double halfWidth;

    /** @param fovDegrees the vertical field of view, in degrees (0 &lt; fov &lt; 180) */
    public PerspectiveCamera(Vec3 eye, Vec3 viewDirection, Vec3 up, double fovDegrees,
            int width, int height) {
        super(eye, viewDirection, up, width, height);
        this.halfHeight = Math.tan(Math.toRadians(fovDegrees) / 2);
        this.halfWidth = halfHeight * width / height;
    }

    /** d = −w + x'·u + y'·v, where (x', y') is the image point on the plane; d is not normalized. */
    @Override
    public Ray generateRay(double x, double y) {
        double a = ndcX(x) * halfWidth;
        double b = ndcY(y) * halfHeight;
        Vec3 d = new Vec3(a * u.x + b * v.x - w.x, a * u.y + b * v.y - w.y, a * u.z + b * v.z - w.z);
        return new Ray(eye, d);
    }
}
