package raylab.camera;

import raylab.math.Vec3;
import raylab.ray.Ray;

/** Parallel projection: every eye ray has direction −w and starts on a rectangle around the eye. */
public final class OrthographicCamera extends Camera {
    private final double halfHeight;
    private final double halfWidth;

    /** @param viewHeight height of the viewed rectangle, in scene units */
    public OrthographicCamera(Vec3 eye, Vec3 viewDirection, Vec3 up, double viewHeight,
            int width, int height) {
        super(eye, viewDirection, up, width, height);
        this.halfHeight = viewHeight / 2;
        this.halfWidth = halfHeight * width / height;
    }

    /** p = eye + x'·u + y'·v, d = −w. */
    @Override
    public Ray generateRay(double x, double y) {
        double a = ndcX(x) * halfWidth;
        double b = ndcY(y) * halfHeight;
        return new Ray(eye.plus(u.times(a)).plus(v.times(b)), w.negate());
    }
}
