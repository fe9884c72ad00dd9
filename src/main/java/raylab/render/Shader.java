package raylab.render;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.material.NormalColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.scene.Scene;
import raylab.shading.Shadows;
import raylab.surface.Surface;

/**
 * The lecture's shading model, run as the plan says:
 * <pre>
 *   L = ka·Ia + Σ_i [ kd·I_i·max(0, n·l_i) + ks·I_i·max(0, n·h_i)^p ]
 * </pre>
 * where the sum runs over lights i that are in front of the surface (n·l_i &gt; 0) and not blocked
 * by a shadow ray. A light exactly at the shaded point has no direction l_i (0/0 gives NaN, and
 * NaN &gt; 0 is false): it is skipped like a light behind the surface and contributes nothing. n is the unit normal turned toward the viewer, v = −d/‖d‖, and l_i the unit
 * direction to light i. One shader per thread: it keeps a scratch record for shadow rays.
 */
public final class Shader {
    private final Scene scene;
    private final Surface root;
    private final RenderPlan plan;
    private final Mode mode;
    private final double depthNear;
    private final double depthFar;
    private final IntersectionRecord scratch = new IntersectionRecord();
    private ShadeListener listener;

    public Shader(Scene scene, Surface root, RenderPlan plan, Mode mode) {
        this.scene = scene;
        this.root = root;
        this.plan = plan;
        this.mode = mode;
        // Depth is shown between the nearest and farthest possible distance to the scene's box.
        var box = root.boundingBox();
        double radius = box.isEmpty() ? 1 : box.extent().length() / 2;
        double center = box.isEmpty() ? 1 : box.centroid().minus(scene.camera.eye).length();
        this.depthNear = Math.max(0, center - radius);
        this.depthFar = center + radius;
    }

    /** Reports every step of shading to {@code l} (null: none). */
    public void listen(ShadeListener l) {
        this.listener = l;
    }

    /** The radiance seen along the ray, whose closest hit is in {@code hit}. */
    public Color shade(Ray ray, IntersectionRecord hit, RenderStats stats) {
        Vec3 n = facing(hit.normal, ray.d);
        if (listener != null) {
            listener.normal(hit.normal, n);
        }
        switch (mode) {
            case NORMALS:
                return NormalColor.of(n);
            case DEPTH:
                double dist = hit.t * ray.d.length();
                double g = 1 - (dist - depthNear) / (depthFar - depthNear);
                return Color.WHITE.times(Math.max(0, Math.min(1, g)));
            default:
                break;
        }
        Material m = hit.material;
        if (!m.isLit()) {
            return mode == Mode.FULL ? m.unlitColor(hit) : Color.BLACK;
        }
        Color L = Color.BLACK;
        if (mode == Mode.FULL && plan.ambient) {
            L = L.plus(m.ka().times(scene.ambient));
            if (listener != null) {
                listener.ambient(L);
            }
        }
        if (!plan.lighting) {
            return mode == Mode.SHADOWS ? Color.WHITE : L;
        }
        Vec3 x = hit.point;
        Vec3 v = ray.d.normalize().negate();
        boolean specular = plan.specular && (plan.bruteForce || m.hasSpecular())
                && (mode == Mode.FULL || mode == Mode.SPECULAR);
        int lights = 0;
        int visible = 0;
        for (int i = 0; i < scene.lights.size(); i++) {
            PointLight light = scene.lights.get(i);
            Vec3 l = light.position.minus(x).normalize();
            if (listener != null) {
                listener.light(light, l, n.dot(l));
            }
            // Written so that NaN fails too: a light exactly at x has no direction (l = 0/0).
            if (!(n.dot(l) > 0)) {
                if (listener != null) {
                    listener.skipped(light, light.position.equals(x)
                            ? "exactly at the point (no direction l): no diffuse, no specular"
                            : "behind the surface (n·l <= 0): no diffuse, no specular");
                }
                continue; // light behind the surface (or at x): neither term contributes
            }
            lights++;
            if (plan.shadows[i]) {
                stats.shadowRays++;
                boolean blocked = Shadows.isShadowed(root, x, n, light, scratch);
                stats.intersectionTests += scratch.tests;
                scratch.tests = 0;
                if (listener != null) {
                    listener.shadow(light, blocked, scratch);
                }
                if (blocked) {
                    stats.shadowRaysBlocked++;
                    continue;
                }
            } else if (listener != null) {
                listener.noShadowRay(light);
            }
            visible++;
            if (mode == Mode.FULL || mode == Mode.DIFFUSE) {
                Color d = m.diffuse(n, l, light.intensity);
                if (listener != null) {
                    listener.diffuse(light, d);
                }
                L = L.plus(d);
            }
            if (specular) {
                stats.specularEvaluations++;
                Color sp = m.specular(n, l, v, light.intensity);
                if (listener != null) {
                    listener.specular(light, sp);
                }
                L = L.plus(sp);
            }
        }
        if (mode == Mode.SHADOWS) {
            return lights == 0 ? Color.BLACK : Color.WHITE.times((double) visible / lights);
        }
        return L;
    }

    /** n turned to face the incoming ray: −n when the ray hits the back side (d·n &gt; 0). */
    public static Vec3 facing(Vec3 n, Vec3 d) {
        return n.dot(d) > 0 ? n.negate() : n;
    }
}
