package raylab.material;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;

/**
 * Shows the geometry without any lighting: the unit outward normal n is drawn as the colour
 * ((n_x + 1)/2, (n_y + 1)/2, (n_z + 1)/2).
 */
public final class NormalColor extends Material {
    public NormalColor(String name) {
        super(name);
    }

    @Override
    public boolean isLit() {
        return false;
    }

    @Override
    public Color unlitColor(IntersectionRecord hit) {
        return of(hit.normal);
    }

    /** The colour that encodes unit vector n. */
    public static Color of(Vec3 n) {
        return new Color((n.x + 1) * 0.5, (n.y + 1) * 0.5, (n.z + 1) * 0.5);
    }
}
