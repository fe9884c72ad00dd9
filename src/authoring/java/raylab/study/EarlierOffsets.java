package raylab.study;

import raylab.light.PointLight;
import raylab.math.Numerics;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * The two shadow-ray offsets the reference used before its local one
 * ({@link raylab.shading.Shadows#isShadowed}, {@link Numerics#offsetRayOrigin}), kept only for the
 * study's comparison (section "Shadow-ray offsets", docs/numerics.md §8). Both move the hit point
 * x along ±n, to the light's side, by an offset that grows with the size of the coordinates:
 * <ul>
 * <li>{@link #hitPointScaled}: 2^-42·max|x_i|: acne near the coordinate origin on a large
 * surface, whose error is that of its large vertices, not of x;</li>
 * <li>{@link #sceneGlobal}: 2^-46·max(max|x_i|, scene magnitude): no acne, but one far object
 * makes the offset large everywhere (a leaf just above the ground leaks light).</li>
 * </ul>
 * Both with the signature of {@code Shadows.isShadowed}; the shadow ray runs from the moved point
 * to the light, blockers 0 &lt; t &lt; 1.
 */
public final class EarlierOffsets {
    /** The relative size of the hit-point offset: 2^-42, about 2^10 units in the last place. */
    public static final double OFFSET_SCALE = 0x1p-42;
    /** The relative size of the scene-global offset: 2^-46, 64 to 128 units in the last place. */
    public static final double SCENE_OFFSET_SCALE = 0x1p-46;

    private EarlierOffsets() {
    }

    /**
     * The hit-point offset: 2^-42·max|x_i| (2^10 ulps of the largest coordinate of x), never less
     * than {@link Numerics#MIN_OFFSET}.
     */
    public static double originOffset(Vec3 x) {
        return Math.max(Numerics.MIN_OFFSET, x.maxAbs() * OFFSET_SCALE);
    }

    /**
     * The scene-global offset: 2^-46·max(max|x_i|, sceneMagnitude) ({@link Numerics#magnitude}
     * of the scene's box), never less than {@link Numerics#MIN_OFFSET}.
     */
    public static double originOffset(Vec3 x, double sceneMagnitude) {
        return Math.max(Numerics.MIN_OFFSET, Math.max(x.maxAbs(), sceneMagnitude) * SCENE_OFFSET_SCALE);
    }

    /** x moved by {@code offset} along n, to the side of the surface that w points into. */
    public static Vec3 moved(Vec3 x, Vec3 n, Vec3 w, double offset) {
        return n.dot(w) >= 0 ? x.plus(n.times(offset)) : x.minus(n.times(offset));
    }

    /** The shadow test with the hit-point offset {@link #originOffset(Vec3)}. */
    public static boolean hitPointScaled(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        return blocked(scene, moved(x, n, light.position.minus(x), originOffset(x)), light, scratch);
    }

    /** The shadow test with the scene-global offset {@link #originOffset(Vec3, double)}. */
    public static boolean sceneGlobal(Surface scene, Vec3 x, Vec3 n, PointLight light,
            IntersectionRecord scratch) {
        double offset = originOffset(x, Numerics.magnitude(scene.boundingBox()));
        return blocked(scene, moved(x, n, light.position.minus(x), offset), light, scratch);
    }

    private static boolean blocked(Surface scene, Vec3 origin, PointLight light, IntersectionRecord scratch) {
        Ray shadowRay = new Ray(origin, light.position.minus(origin), Double.MIN_VALUE, Math.nextDown(1.0));
        return scene.intersectsAny(shadowRay, scratch);
    }
}
