package raylab.shading;

import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;

/** The lecture's loop with a classic blunder. */
public final class Shading {
    private Shading() {
    }

    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        Color result = Color.BLACK;
        for (PointLight light : lights) {
            result = result.plus(at.ambient()); // BUG: the ambient term once per light
            Vec3 l = at.toLight(light);
            if (at.n.dot(l) > 0 && at.visible(light)) {
                result = result.plus(at.diffuse(light, l)).plus(at.specular(light, l));
            }
        }
        return result;
    }
}
