package raylab.shading;

import java.util.List;

import raylab.course.NotImplemented;
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
        Color result = Color.BLACK; // BUG: the ambient term ka·Ia left out
        for (PointLight light : lights) {
            Vec3 l = at.toLight(light);
            if (!(at.n.dot(l) > 0)) {
                continue; // behind the surface: no light at all, and no shadow ray
            }
            if (!at.visible(light)) {
                continue; // in shadow
            }
            result = result.plus(at.diffuse(light, l)).plus(at.specular(light, l));
        }
        return result;
    }
}
