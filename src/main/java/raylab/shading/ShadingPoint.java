package raylab.shading;

import java.util.function.Predicate;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;

/**
 * A surface point being shaded, as {@link Shading#shade} sees it: the point x, the unit normal n
 * turned toward the viewer, the unit direction v to the viewer, and the material; and the
 * framework's answers to the questions of the lecture's {@code shade()}: the ambient term, the
 * direction to a light, whether a light is visible (the shadow test, traced only when the render
 * plan says it can matter), and the diffuse and specular terms of one light.
 *
 * <p>The framework (the renderer, or a test) decides how each question is answered: in a debug
 * mode some terms are black, a scene without shadows answers "visible" without tracing a ray, and
 * the counters and {@code raylab trace} hear every step.
 */
public final class ShadingPoint {
    /** The point x being shaded. */
    public final Vec3 x;
    /** The unit normal at x, turned toward the viewer (n·v ≥ 0). */
    public final Vec3 n;
    /** The unit direction from x toward the viewer, v = −d/‖d‖. */
    public final Vec3 v;
    /** The material at x. */
    public final Material material;
    private final Answers answers;

    /** How the framework answers a shading point's questions. */
    public interface Answers {
        /** ka·Ia, or black where the plan or mode leaves the ambient term out. */
        Color ambient(ShadingPoint at);

        /** Hears that the loop looked at a light (for traces). */
        default void lookedAt(ShadingPoint at, PointLight light, Vec3 l) {
        }

        /** Whether nothing blocks the light from x (a shadow ray, if the plan traces one). */
        boolean visible(ShadingPoint at, PointLight light);

        /** The light's diffuse term at x. */
        Color diffuse(ShadingPoint at, PointLight light, Vec3 l);

        /** The light's specular term at x. */
        Color specular(ShadingPoint at, PointLight light, Vec3 l);
    }

    public ShadingPoint(Vec3 x, Vec3 n, Vec3 v, Material material, Answers answers) {
        this.x = x;
        this.n = n;
        this.v = v;
        this.material = material;
        this.answers = answers;
    }

    /** The ambient term ka·Ia (black when the scene has none). */
    public Color ambient() {
        return answers.ambient(this);
    }

    /**
     * The unit direction l = (q − x)/‖q − x‖ from x toward the light at q. A light exactly at x
     * has no direction: then l = (0, 0, 0), so n·l = 0 and the light counts as not in front.
     */
    public Vec3 toLight(PointLight light) {
        Vec3 d = light.position.minus(x);
        Vec3 l = d.lengthSquared() == 0 ? Vec3.ZERO : d.normalize();
        answers.lookedAt(this, light, l);
        return l;
    }

    /**
     * Whether the light is visible from x: nothing blocks the segment between them (milestone
     * {@code shadows} writes the test, {@link Shadows#isShadowed}). Where the render plan knows
     * that nothing can block the light, no shadow ray is traced and the answer is yes.
     */
    public boolean visible(PointLight light) {
        return answers.visible(this, light);
    }

    /** The diffuse term of the light: kd·I·max(0, n·l) for a Lambertian material (milestone lambert). */
    public Color diffuse(PointLight light, Vec3 l) {
        return answers.diffuse(this, light, l);
    }

    /** The specular term of the light: ks·I·max(0, n·h)^p for Blinn-Phong (milestone phong), else black. */
    public Color specular(PointLight light, Vec3 l) {
        return answers.specular(this, light, l);
    }

    /**
     * A point with everything on, for tests: ka·Ia with the given Ia, the material's own terms,
     * and the given answer to "is this light visible?".
     */
    public static ShadingPoint plain(Vec3 x, Vec3 n, Vec3 v, Material m, Color ia,
            Predicate<PointLight> visible) {
        return new ShadingPoint(x, n, v, m, new Answers() {
            @Override
            public Color ambient(ShadingPoint at) {
                return at.material.ka().times(ia);
            }

            @Override
            public boolean visible(ShadingPoint at, PointLight light) {
                return visible.test(light);
            }

            @Override
            public Color diffuse(ShadingPoint at, PointLight light, Vec3 l) {
                return at.material.diffuse(at.n, l, light.intensity);
            }

            @Override
            public Color specular(ShadingPoint at, PointLight light, Vec3 l) {
                return at.material.specular(at.n, l, at.v, light.intensity);
            }
        });
    }
}
