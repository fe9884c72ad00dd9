package raylab.render;

import java.util.ArrayList;
import java.util.List;

import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.Vec3;
import raylab.scene.Scene;
import raylab.surface.Surface;

/**
 * What a render must compute, derived from the scene before any ray is traced: the renderer
 * runs nothing that the plan leaves out. Each decision keeps the reason it was made, which
 * {@code raylab render} prints.
 *
 * <p>Every decision is a proven no-op: leaving out what the plan leaves out changes no pixel.
 * {@link #bruteForce(Scene)} is the plan that leaves nothing out (the test
 * {@code PlanVersusBruteForceTest} renders random scenes both ways and requires the same image).
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
    /**
     * Whether this is the brute-force plan: specular terms evaluated for every lit material
     * (also with ks = 0), ka·Ia added whenever the scene allows it, shadow rays toward every light
     * that casts shadows, and a linear group of every primitive (meshes split into triangles).
     */
    public final boolean bruteForce;
    private final List<String> lines = new ArrayList<>();

    /**
     * The brute-force plan of a scene: no shortcut at all. Only what the scene itself says is kept
     * (a light with {@code "shadows": false}, an effect switched off with {@code false}), because
     * that changes the image by definition; every decision the plan would infer is left out.
     */
    public static RenderPlan bruteForce(Scene scene) {
        return new RenderPlan(scene, true);
    }

    public RenderPlan(Scene scene) {
        this(scene, false);
    }

    private RenderPlan(Scene scene, boolean brute) {
        bruteForce = brute;
        if (brute) {
            lighting = true;
            ambient = !Boolean.FALSE.equals(scene.effects.ambient());
            specular = !Boolean.FALSE.equals(scene.effects.specular());
            shadows = new boolean[scene.lights.size()];
            note("brute force", "every shortcut of the plan is off");
            note("lighting", "on: the light loop runs at every lit point (" + scene.lights.size() + " light(s))");
            note("ambient", ambient ? "on: ka·Ia added at every lit point, even when zero"
                    : "off: switched off by the scene");
            note("specular", specular ? "on: evaluated for every lit material, even with ks = 0"
                    : "off: switched off by the scene");
            for (int i = 0; i < shadows.length; i++) {
                PointLight light = scene.lights.get(i);
                String why;
                if (Boolean.FALSE.equals(scene.effects.shadows())) {
                    why = "off: switched off by the scene";
                } else if (!light.castsShadows) {
                    why = "off: the light casts no shadows";
                } else {
                    shadows[i] = true;
                    why = "on: a shadow ray at every lit point facing the light";
                }
                note("shadows of " + light.name, why);
            }
            samplesPerPixel = scene.samplesPerPixel;
            note("samples", samplesPerPixel == 1 ? "1 per pixel, through the pixel centre"
                    : samplesPerPixel + " per pixel, " + scene.sampler.name().toLowerCase());
            acceleration = false;
            note("acceleration", "off: linear group of all " + scene.primitiveCount()
                    + " primitive(s), meshes split into triangles");
            return;
        }
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
        boolean canBlock = !scene.surfaces.isEmpty() && !seenFromOutsideOnly(scene);
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
                why = "off: a single convex surface seen from outside cannot shadow itself";
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

    /** Relative margin by which the eye must lie outside the convex surface. */
    static final double OUTSIDE_MARGIN = 1e-6;

    /**
     * Whether the scene is one sphere or one box seen by a perspective camera whose eye is
     * clearly outside it. Then no shadow ray can be blocked, which is why none is traced:
     * <ul>
     * <li>every eye ray starts at the eye, outside the convex solid K, so its closest hit x is
     * where it enters K, and the normal n turned toward the viewer is the outward normal;
     * <li>K lies in the half-space n·(y − x) ≤ 0 behind the plane through x (a tangent plane of
     * the sphere, the plane of the box face that was hit);
     * <li>only lights with n·l &gt; 0 get a shadow ray, and the points x + t(q − x), 0 &lt; t &lt; 1,
     * then have n·(y − x) = t n·(q − x) &gt; 0: none lies in K, so nothing blocks the light.
     * </ul>
     * With the eye inside (or on) the solid, eye rays hit the inside of the far wall, whose
     * normal faces inward; a light inside the solid is then in front of that wall but the near
     * wall may be between (for a box: another face), so shadow rays are needed. An orthographic
     * camera starts its rays on a whole rectangle, so the rule is not applied to it at all.
     * The margin (a millionth of the size) keeps eye rays that start a rounding error away from
     * the surface out of the rule.
     */
    static boolean seenFromOutsideOnly(Scene scene) {
        if (scene.surfaces.size() != 1 || !(scene.camera instanceof PerspectiveCamera)) {
            return false;
        }
        Surface s = scene.surfaces.get(0);
        Vec3 eye = scene.camera.eye;
        // The surface's type says (raylab.scene.SurfaceType.eyeOutsideConvex: the sphere, the box).
        for (raylab.scene.SurfaceType t : raylab.scene.SurfaceTypes.all().values()) {
            Boolean outside = t.eyeOutsideConvex(s, eye, OUTSIDE_MARGIN);
            if (outside != null) {
                return outside;
            }
        }
        return false;
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
        if (bruteForce) {
            return new raylab.surface.Group(primitives(scene.surfaces), "scene (brute force)");
        }
        return acceleration ? new raylab.surface.Bvh(scene.surfaces, "scene")
                : new raylab.surface.Group(scene.surfaces, "scene");
    }

    /**
     * Every primitive of the surfaces, in order: groups split into their members, and surfaces
     * made of primitives into those (raylab.scene.SurfaceType.primitives: a mesh's triangles).
     */
    public static List<Surface> primitives(List<Surface> surfaces) {
        List<Surface> out = new ArrayList<>();
        for (Surface s : surfaces) {
            if (s instanceof raylab.surface.Group g) {
                out.addAll(primitives(g.members()));
            } else {
                out.addAll(madeOf(s));
            }
        }
        return out;
    }

    private static List<Surface> madeOf(Surface s) {
        for (raylab.scene.SurfaceType t : raylab.scene.SurfaceTypes.all().values()) {
            List<Surface> parts = t.primitives(s);
            if (parts != null) {
                return parts;
            }
        }
        return List.of(s);
    }
}
