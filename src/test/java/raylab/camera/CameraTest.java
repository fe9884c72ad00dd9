package raylab.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import raylab.math.Vec3;
import raylab.ray.Ray;

/** Camera frames and eye rays, with expected angles worked out with tan by hand. */
class CameraTest {
    private static final double EPS = 1e-12;

    private static double angleDegrees(Vec3 a, Vec3 b) {
        double c = a.dot(b) / (a.length() * b.length());
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, c))));
    }

    private static void assertVec(Vec3 expected, Vec3 actual, String what) {
        assertTrue(expected.minus(actual).length() < EPS, what + ": expected " + expected + ", got " + actual);
    }

    @Test
    void frameOfTheStandardView() {
        Camera cam = new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -2), new Vec3(0, 3, 0), 60, 40, 30);
        assertVec(new Vec3(1, 0, 0), cam.u, "u (right)");
        assertVec(new Vec3(0, 1, 0), cam.v, "v (up)");
        assertVec(new Vec3(0, 0, 1), cam.w, "w (backward)");
    }

    @Test
    void frameIsOrthonormalAndRightHanded() {
        Vec3 view = new Vec3(1, 2, -3);
        Vec3 up = new Vec3(0.1, 1, 0.2);
        Camera cam = new PerspectiveCamera(new Vec3(4, 5, 6), view, up, 45, 16, 9);
        assertEquals(1, cam.u.length(), EPS, "|u|");
        assertEquals(1, cam.v.length(), EPS, "|v|");
        assertEquals(1, cam.w.length(), EPS, "|w|");
        assertEquals(0, cam.u.dot(cam.v), EPS, "u.v");
        assertEquals(0, cam.v.dot(cam.w), EPS, "v.w");
        assertEquals(0, cam.w.dot(cam.u), EPS, "w.u");
        assertVec(view.normalize().negate(), cam.w, "w = -view/|view|");
        assertVec(cam.w, cam.u.cross(cam.v), "u x v = w");
        assertEquals(0, cam.u.dot(up), EPS, "u is perpendicular to up");
        assertTrue(cam.v.dot(up) > 0, "v leans toward up: v=" + cam.v);
    }

    @ParameterizedTest(name = "fov {0}, {1}x{2}")
    @CsvSource({"90, 64, 64", "60, 80, 40", "30, 33, 17", "120, 10, 30"})
    void perspectiveRaysMakeTheFieldOfView(double fov, int width, int height) {
        Vec3 view = new Vec3(2, -1, -4);
        Vec3 eye = new Vec3(1, 2, 3);
        PerspectiveCamera cam = new PerspectiveCamera(eye, view, new Vec3(0, 1, 0), fov, width, height);
        double aspect = (double) width / height;
        double tanHalf = Math.tan(Math.toRadians(fov) / 2);

        Ray centre = cam.generateRay(width / 2.0, height / 2.0);
        assertEquals(eye, centre.p, "perspective rays start at the eye");
        assertEquals(0, angleDegrees(centre.d, view), 1e-6, "centre ray " + centre + " along view " + view);

        Ray top = cam.generateRay(width / 2.0, 0);
        assertEquals(fov / 2, angleDegrees(top.d, view), 1e-9, "top edge centre is fov/2 from the view");
        assertTrue(top.d.dot(cam.v) > 0, "y = 0 is the top of the image: " + top);

        Ray left = cam.generateRay(0, height / 2.0);
        double expectedHorizontal = Math.toDegrees(Math.atan(tanHalf * aspect));
        assertEquals(expectedHorizontal, angleDegrees(left.d, view), 1e-9,
                "left edge is atan(tan(fov/2) * aspect) from the view");
        assertTrue(left.d.dot(cam.u) < 0, "x = 0 is the left of the image: " + left);

        // corner: direction -w + a u + b v with |a| = tan(fov/2) aspect, |b| = tan(fov/2)
        double expectedCorner = Math.toDegrees(Math.acos(1 / Math.sqrt(1 + tanHalf * tanHalf * (1 + aspect * aspect))));
        for (double[] corner : new double[][] {{0, 0}, {width, 0}, {0, height}, {width, height}}) {
            Ray r = cam.generateRay(corner[0], corner[1]);
            assertEquals(expectedCorner, angleDegrees(r.d, view), 1e-9,
                    "corner (" + corner[0] + ", " + corner[1] + ") ray " + r);
        }
        // pixel centres
        assertEquals(cam.generateRay(0.5, 0.5).d, cam.rayThroughPixelCenter(0, 0).d, "centre of pixel (0,0)");
        assertEquals(cam.generateRay(width - 0.5, height - 0.5).d,
                cam.rayThroughPixelCenter(width - 1, height - 1).d, "centre of the last pixel");
    }

    @Test
    void centrePixelOfAnOddImageLooksAlongTheView() {
        Vec3 view = new Vec3(-1, 0.5, 2);
        PerspectiveCamera cam = new PerspectiveCamera(new Vec3(3, 0, 0), view, new Vec3(0, 1, 0), 50, 31, 21);
        Ray r = cam.rayThroughPixelCenter(15, 10);
        assertEquals(0, angleDegrees(r.d, view), 1e-6, "centre pixel ray " + r);
    }

    @Test
    void orthographicRaysAreParallelAndSpanTheViewHeight() {
        Vec3 eye = new Vec3(0, 1, 5);
        Vec3 view = new Vec3(0, 0, -3);
        double viewHeight = 4;
        int width = 60;
        int height = 30;
        OrthographicCamera cam = new OrthographicCamera(eye, view, new Vec3(0, 1, 0), viewHeight, width, height);
        for (int iy = 0; iy < height; iy += 7) {
            for (int ix = 0; ix < width; ix += 9) {
                Ray r = cam.rayThroughPixelCenter(ix, iy);
                assertVec(new Vec3(0, 0, -1), r.d.normalize(), "direction of pixel (" + ix + ", " + iy + ")");
                assertEquals(0, r.p.minus(eye).dot(cam.w), EPS, "origin in the plane through the eye: " + r);
            }
        }
        assertVec(eye, cam.generateRay(width / 2.0, height / 2.0).p, "centre ray starts at the eye");
        Vec3 top = cam.generateRay(width / 2.0, 0).p;
        Vec3 bottom = cam.generateRay(width / 2.0, height).p;
        assertVec(new Vec3(0, viewHeight, 0), top.minus(bottom), "top minus bottom origin = viewHeight v");
        Vec3 left = cam.generateRay(0, height / 2.0).p;
        Vec3 right = cam.generateRay(width, height / 2.0).p;
        assertVec(new Vec3(viewHeight * width / height, 0, 0), right.minus(left),
                "right minus left origin = viewHeight * aspect u");
    }

    @Test
    void frameExistsUnlessUpIsParallelToTheView() {
        assertTrue(Camera.frameExists(new Vec3(0, 0, -1), new Vec3(0, 1, 0)), "usual frame");
        assertTrue(Camera.frameExists(new Vec3(0, 0, -1), new Vec3(0, 1, 1)), "tilted up");
        assertFalse(Camera.frameExists(new Vec3(0, 1, 0), new Vec3(0, 1, 0)), "up equal to view");
        assertFalse(Camera.frameExists(new Vec3(0, -2, 0), new Vec3(0, 5, 0)), "up opposite to view");
        assertFalse(Camera.frameExists(new Vec3(1, 2, 3), new Vec3(2, 4, 6)), "up a multiple of view");
        assertFalse(Camera.frameExists(new Vec3(0, 0, -1), Vec3.ZERO), "zero up");
        assertFalse(Camera.frameExists(Vec3.ZERO, new Vec3(0, 1, 0)), "zero view direction");
        assertTrue(Camera.frameExists(new Vec3(0, 0, -1e-5), new Vec3(0, 1e-5, 0)), "small but valid vectors");
    }
}
