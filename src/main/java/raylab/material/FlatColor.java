package raylab.material;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;

/** One colour wherever the surface is seen, whatever the lights: "white where the ray hits". */
public final class FlatColor extends Material {
    public final Color color;

    public FlatColor(Color color, String name) {
        super(name);
        this.color = color;
    }

    @Override
    public boolean isLit() {
        return false;
    }

    @Override
    public Color unlitColor(IntersectionRecord hit) {
        return color;
    }
}
