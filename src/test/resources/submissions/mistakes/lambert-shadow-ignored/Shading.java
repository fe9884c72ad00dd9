package raylab.shading;

import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;

/** The lecture's loop without its shadow test. */
public final class Shading {
    private Shading() {
    }

    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        Color result = at.ambient();
        for (PointLight light : lights) {
            Vec3 l = at.toLight(light);
            if (at.n.dot(l) > 0) { // BUG: at.visible(light) never asked: shadows are lit
                result = result.plus(at.diffuse(light, l)).plus(at.specular(light, l));
            }
        }
        return result;
    }
}
