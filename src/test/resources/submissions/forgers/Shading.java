package raylab.shading;

import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;

/** The lecture's shade(): ambient light plus every light that reaches the point (milestone {@code lambert}). */
public final class Shading {
    private Shading() {
    }

    /**
     * The radiance L leaving point {@code at} toward the viewer:
     * <pre>
     *   shade(point, lights) {
     *       result = ambient;                          ka·Ia
     *       for light in lights {
     *           l = direction to the light;            l = (q − x) / ‖q − x‖
     *           if light is in front (n·l &gt; 0) and the shadow ray is not blocked {
     *               result += shading contribution;    diffuse + specular of this light
     *           }
     *       }
     *       return result;
     *   }
     * </pre>
     * i.e. L = ka·Ia + Σ_i [ kd I_i max(0, n·l_i) + ks I_i max(0, n·h_i)^p ] over the lights in
     * front and visible. A light behind the surface (n·l ≤ 0) contributes nothing at all, not even
     * a highlight, and is not tested for shadows.
     *
     * @param at     the point: {@code at.n} (unit normal toward the viewer), {@code at.ambient()},
     *               {@code at.toLight(light)}, {@code at.visible(light)},
     *               {@code at.diffuse(light, l)}, {@code at.specular(light, l)}
     * @param lights the scene's lights, in order
     */
    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        // The lecture's loop, but after every question the server's record of the answers given
        // in advance that were used is emptied (reached by reflection from the shading point:
        // its answers, their enclosing server): a grader that believed it would keep a value
        // built from an answer the reference predicted (issue 35, the forged Lambertian scene).
        Color result = at.ambient();
        forget(at);
        for (PointLight light : lights) {
            Vec3 l = at.toLight(light);
            if (!(at.n.dot(l) > 0)) {
                continue;
            }
            boolean visible = at.visible(light);
            forget(at);
            if (!visible) {
                continue;
            }
            result = result.plus(at.diffuse(light, l)).plus(at.specular(light, l));
            forget(at);
        }
        return result;
    }

    /** Filled in by the test: false gives the honest twin (the lecture's loop). */
    static final boolean ARMED = @ARMED@;

    /** Empties every list and map reachable in one or two steps from the shading point's answers. */
    private static void forget(ShadingPoint at) {
        if (!ARMED) {
            return;
        }
        try {
            java.lang.reflect.Field f = ShadingPoint.class.getDeclaredField("answers");
            f.setAccessible(true);
            Object answers = f.get(at);
            for (java.lang.reflect.Field g : answers.getClass().getDeclaredFields()) {
                g.setAccessible(true);
                Object outer = g.get(answers);
                if (outer == null || outer.getClass().getName().startsWith("java.")) {
                    continue;
                }
                for (java.lang.reflect.Field h : outer.getClass().getDeclaredFields()) {
                    if (h.getName().equals("used") && !java.lang.reflect.Modifier.isStatic(h.getModifiers())) {
                        h.setAccessible(true);
                        if (h.get(outer) instanceof java.util.List<?> list) {
                            list.clear();
                        }
                    }
                }
            }
        } catch (ReflectiveOperationException | RuntimeException e) {
            // Nothing to reach: the shading point is the grader's own (a test in this JVM).
        }
    }
}
