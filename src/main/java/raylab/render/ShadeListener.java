package raylab.render;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;

/**
 * Hears each step of {@link Shader#shade}, for {@code raylab trace}. Rendering uses none, so the
 * hot path pays one null check per step.
 */
public interface ShadeListener {
    /** The normal used for shading, after turning it toward the viewer. */
    default void normal(Vec3 outward, Vec3 facing) {
    }

    /** The ambient term ka·Ia was added. */
    default void ambient(Color term) {
    }

    /** Light i is considered: unit direction l and the cosine n·l. */
    default void light(PointLight light, Vec3 l, double nDotL) {
    }

    /** A shadow ray was traced; {@code blocker} holds the blocking hit when blocked. */
    default void shadow(PointLight light, boolean blocked, IntersectionRecord blocker) {
    }

    /** Light skipped entirely, and why. */
    default void skipped(PointLight light, String why) {
    }

    /** The plan traces no shadow ray toward this light. */
    default void noShadowRay(PointLight light) {
    }

    /** The diffuse term of a light. */
    default void diffuse(PointLight light, Color term) {
    }

    /** The specular term of a light. */
    default void specular(PointLight light, Color term) {
    }
}
