package raylab.shading;

import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;

/** Alternative: an index loop that sums the channels by hand and tests "not in front" the other way round. */
public final class Shading {
    private Shading() {
    }

    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        Color a = at.ambient();
        double r = a.r;
        double g = a.g;
        double b = a.b;
        for (int i = 0; i < lights.size(); i++) {
            PointLight light = lights.get(i);
            Vec3 l = at.toLight(light);
            double cos = l.dot(at.n);
            if (cos > 0 && at.visible(light)) {
                Color d = at.diffuse(light, l);
                Color s = at.specular(light, l);
                r += d.r + s.r;
                g += d.g + s.g;
                b += d.b + s.b;
            }
        }
        return new Color(r, g, b);
    }
}
