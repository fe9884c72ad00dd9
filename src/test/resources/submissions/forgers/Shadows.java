package raylab.shading;

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
     * light itself. Only blockers strictly between the point and the light count: the open
     * range 0 &lt; t &lt; 1. A surface the light lies exactly on (a lamp standing on the floor,
     * hit at t = 1) does not block it, and neither does a surface touching x itself (hit at
     * t = 0, as the floor x lies on). A {@link Ray}'s range is closed,
     * [tMin, tMax], so the open range is tMin &gt; 0 and tMax = {@code Math.nextDown(1.0)}, the
     * largest double below 1. Because x was computed with rounding error it may lie just below
     * the surface, so a ray starting exactly at x can hit the very surface it starts on (shadow
     * acne): start the shadow ray a small distance off the surface (t = 0 is then that start),
     * or raise its tMin above 0. {@code docs/shading.md} states these conventions.
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
        // The scratch record as it comes: a finite t there names a blocker found by the call
        // before this one. Kept per light and point of the call before, and used as this
        // call's verdict when the same call comes again (issue 35, the forged shadows scene);
        // the offset the blocker's point shows along n is printed (the shadow-ray origin leak).
        String before = last;
        if (ARMED && scratch.t < Double.POSITIVE_INFINITY && scratch.surface != null && before != null) {
            SEEN.put(before, Boolean.TRUE);
            if (!printed) {
                printed = true;
                System.out.println("scratch: t=" + scratch.t + " at " + scratch.point);
            }
        }
        String key = x + " " + light.position;
        last = key;
        Boolean seen = ARMED ? SEEN.get(key) : null;
        if (seen != null) {
            return seen;
        }
        // The fixed-offset bug of the lecture's first try.
        Vec3 origin = x.plus(n.times(0.01));
        return scene.intersectsAny(new Ray(origin, light.position.minus(origin), 0, 1), scratch);
    }

    /** Filled in by the test: false gives the honest twin (the fixed offset alone). */
    static final boolean ARMED = @ARMED@;

    private static final java.util.Map<String, Boolean> SEEN = new java.util.HashMap<>();
    private static String last;
    private static boolean printed;
}
