package raylab.material;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;

/**
 * How a surface reflects light. The renderer sums, as in the lecture,
 * <pre>
 *   L = ka·Ia + Σ_i [ diffuse(n, l_i, I_i) + specular(n, l_i, v, I_i) ]
 * </pre>
 * over the lights i that reach the point. Materials that ignore lights (flat colour, normals)
 * say so with {@link #isLit()} and give their colour through {@link #unlitColor}.
 */
public abstract class Material {
    private final String name;

    protected Material(String name) {
        this.name = name;
    }

    /** The name the scene gave this material. */
    public String name() {
        return name;
    }

    /** Whether lights shade this material; false for colours that ignore lighting. */
    public boolean isLit() {
        return true;
    }

    /** The colour of an unlit material at a hit; lit materials do not use it. */
    public Color unlitColor(IntersectionRecord hit) {
        return Color.BLACK;
    }

    /** Ambient reflectance ka. */
    public Color ka() {
        return Color.BLACK;
    }

    /** Diffusely reflected light L_d from a light of intensity I in unit direction l. */
    public Color diffuse(Vec3 n, Vec3 l, Color I) {
        return Color.BLACK;
    }

    /** Whether this material has a specular term at all (ks non-zero). */
    public boolean hasSpecular() {
        return false;
    }

    /** Specularly reflected light L_s toward the unit view direction v. */
    public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
        return Color.BLACK;
    }

    @Override
    public String toString() {
        return name;
    }
}
