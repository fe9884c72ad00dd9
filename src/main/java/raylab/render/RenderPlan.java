package raylab.render;

import java.util.ArrayList;
import java.util.List;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.scene.Scene;
import raylab.surface.Surface;

/**
 * What a render must compute, derived from the scene before any ray is traced: the renderer
 * runs nothing that the plan leaves out. Each decision keeps the reason it was made, which
 * {@code raylab render} prints.
 */
public final class RenderPlan {
    /** Primitive count from which a bounding volume hierarchy pays for itself. */
    public static final int ACCELERATION_THRESHOLD = 16;

    /** Whether any lit material is seen by any light (else no light loop at all). */
    public final boolean lighting;
    /** Whether to add ka·Ia. */
    public final boolean ambient;
    /** Whether to evaluate specular terms (only for materials whose ks is non-zero). */
    public final boolean specular;
    /** For each light of the scene, in order: whether to trace shadow rays toward it. */
    public final boolean[] shadows;
    /** Samples per pixel (1 = one ray through each pixel centre). */
    public final int samplesPerPixel;
    /** Whether to trace through a bounding volume hierarchy rather than a linear group. */
    public final boolean acceleration;
    private final List<String> lines = new ArrayList<>();

    public RenderPlan(Scene scene) {
        List<Material> lit = scene.materials().stream().filter(Material::isLit).toList();
        int primitives = scene.primitiveCount();

        lighting = !lit.isEmpty() && !scene.lights.isEmpty();
        if (lit.isEmpty()) {
            note("lighting", "off: no material reflects light");
        } else if (scene.lights.isEmpty()) {
            note("lighting", "off: the scene has no lights");
        } else {
            note("lighting", scene.lights.size() + " light(s), " + lit.size() + " lit material(s)");
        }

        // ka is asked for only once the scene's switch and Ia leave the ambient term possible.
        long withKa = Boolean.FALSE.equals(scene.effects.ambient()) || scene.ambient.isBlack() ? 0
                : lit.stream().filter(m -> !m.ka().isBlack()).count();
        if (Boolean.FALSE.equals(scene.effects.ambient())) {
            ambient = false;
            note("ambient", "off: switched off by the scene");
        } else if (scene.ambient.isBlack()) {
            ambient = false;
            note("ambient", "off: Ia is zero");
        } else if (withKa == 0) {
            ambient = false;
            note("ambient", "off: no material has ka > 0");
        } else {
            ambient = true;
            note("ambient", "on: Ia = " + scene.ambient + ", " + withKa + " material(s) with ka > 0");
        }

        long withKs = lit.stream().filter(Material::hasSpecular).count();
        if (!lighting) {
            specular = false;
            note("specular", "off: no lighting");
        } else if (Boolean.FALSE.equals(scene.effects.specular())) {
            specular = false;
            note("specular", "off: switched off by the scene");
        } else if (withKs == 0) {
            specular = false;
            note("specular", "off: no material has ks > 0");
        } else {
            specular = true;
            note("specular", "on for " + withKs + " of " + lit.size() + " lit material(s) (ks > 0)");
        }

        shadows = new boolean[scene.lights.size()];
        boolean canBlock = !(scene.surfaces.size() == 1 && scene.surfaces.get(0).isConvex())
                && !scene.surfaces.isEmpty();
        for (int i = 0; i < shadows.length; i++) {
            PointLight light = scene.lights.get(i);
            String why;
            if (!lighting) {
                why = "off: no lighting";
            } else if (Boolean.FALSE.equals(scene.effects.shadows())) {
                why = "off: switched off by the scene";
            } else if (!light.castsShadows) {
                why = "off: the light casts no shadows";
            } else if (!canBlock) {
                why = "off: a single convex surface cannot shadow itself";
            } else {
                shadows[i] = true;
                why = "on";
            }
            note("shadows of " + light.name, why);
        }

        samplesPerPixel = scene.samplesPerPixel;
        note("samples", samplesPerPixel == 1 ? "1 per pixel, through the pixel centre"
                : samplesPerPixel + " per pixel, " + scene.sampler.name().toLowerCase());

        Boolean accel = scene.effects.acceleration();
        if (Boolean.FALSE.equals(accel)) {
            acceleration = false;
            note("acceleration", "off: switched off by the scene (linear group of "
                    + scene.surfaces.size() + ")");
        } else if (Boolean.TRUE.equals(accel)) {
            acceleration = true;
            note("acceleration", "BVH over " + scene.surfaces.size() + " surface(s): switched on by the scene");
        } else if (primitives >= ACCELERATION_THRESHOLD) {
            acceleration = true;
            note("acceleration", "BVH over " + scene.surfaces.size() + " surface(s), "
                    + primitives + " primitives (>= " + ACCELERATION_THRESHOLD + ")");
        } else {
            acceleration = false;
            note("acceleration", "off: " + primitives + " primitive(s), linear group (< "
                    + ACCELERATION_THRESHOLD + ")");
        }
    }

    private void note(String what, String why) {
        lines.add(String.format("  %-22s %s", what, why));
    }

    /** Whether any light needs shadow rays. */
    public boolean anyShadows() {
        for (boolean s : shadows) {
            if (s) {
                return true;
            }
        }
        return false;
    }

    /** The plan as lines of text, one decision per line with its reason. */
    public List<String> describe() {
        return List.copyOf(lines);
    }

    /** The surface to trace against: the scene's surfaces in a hierarchy or a linear group (which counts tests). */
    public Surface root(Scene scene) {
        return acceleration ? new raylab.surface.Bvh(scene.surfaces, "scene")
                : new raylab.surface.Group(scene.surfaces, "scene");
    }
}
