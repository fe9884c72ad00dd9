package raylab.shading;

import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;

/** The lecture's loop with the shadow test around the diffuse term only. */
public final class Shading {
    private Shading() {
    }

    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        Color result = at.ambient();
        for (PointLight light : lights) {
            Vec3 l = at.toLight(light);
            if (at.n.dot(l) > 0) {
                if (at.visible(light)) {
                    result = result.plus(at.diffuse(light, l));
                }
                result = result.plus(at.specular(light, l)); // BUG: a blocked light keeps its highlight
            }
        }
        return result;
    }
}
