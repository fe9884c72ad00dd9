package raylab.light;

import raylab.math.Color;
import raylab.math.Vec3;

/**
 * A point light at a position, with intensity I. Its light does not fall off with distance
 * (the lecture's model); a surface point receives I from it unless a shadow ray is blocked.
 */
public final class PointLight {
    public final Vec3 position;
    public final Color intensity;
    /** False for a light whose shadows the scene switched off. */
    public final boolean castsShadows;
    public final String name;

    public PointLight(Vec3 position, Color intensity, boolean castsShadows, String name) {
        this.position = position;
        this.intensity = intensity;
        this.castsShadows = castsShadows;
        this.name = name;
    }

    @Override
    public String toString() {
        return name;
    }
}
