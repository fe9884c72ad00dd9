package raylab.camera;

import raylab.math.Vec3;
import raylab.ray.Ray;

/**
 * Makes eye rays. The camera looks from {@code eye} along the view direction; u, v, w is its
 * orthonormal frame (u to the right, v up, w pointing backward, away from the view).
 *
 * <p>Image coordinates (x, y) are continuous: pixel (ix, iy) covers [ix, ix+1) × [iy, iy+1),
 * with (0, 0) the top-left corner, so its centre is (ix + 0.5, iy + 0.5).
 */
public abstract class Camera {
    public final Vec3 eye;
    public final Vec3 u;
    public final Vec3 v;
    public final Vec3 w;
    protected final int width;
    protected final int height;

    protected Camera(Vec3 eye, Vec3 viewDirection, Vec3 up, int width, int height) {
        this.eye = eye;
        this.w = viewDirection.negate().normalize();
        this.u = up.cross(w).normalize();
        this.v = w.cross(u);
        this.width = width;
        this.height = height;
    }

    /** The eye ray through image point (x, y), in pixel units from the top-left corner. */
    public abstract Ray generateRay(double x, double y);

    /** The eye ray through the centre of pixel (ix, iy). */
    public Ray rayThroughPixelCenter(int ix, int iy) {
        return generateRay(ix + 0.5, iy + 0.5);
    }

    /** Horizontal image-plane coordinate of x, from −1 (left edge) to 1 (right edge). */
    protected double ndcX(double x) {
        return 2 * x / width - 1;
    }

    /** Vertical image-plane coordinate of y, from 1 (top edge) to −1 (bottom edge). */
    protected double ndcY(double y) {
        return 1 - 2 * y / height;
    }

    /** Whether up and the view direction are not parallel, so that the frame exists. */
    public static boolean frameExists(Vec3 viewDirection, Vec3 up) {
        Vec3 c = up.cross(viewDirection);
        return c.isFinite() && c.length() > 1e-9 * up.length() * viewDirection.length();
    }
}
