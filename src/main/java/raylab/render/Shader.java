package raylab.render;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.material.NormalColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.scene.Scene;
import raylab.shading.Shading;
import raylab.shading.ShadingPoint;
import raylab.shading.Shadows;
import raylab.surface.Surface;

/**
 * The lecture's shading model, run as the plan says. The loop over the lights is the student's
 * {@link Shading#shade} (milestone lambert); this class answers its questions (ambient term,
 * shadow test, diffuse and specular terms) as the plan and the debug mode say:
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
        double[] range = mode == Mode.DEPTH ? depthRange(scene, root) : new double[] {0, 1};
        this.depthNear = range[0];
        this.depthFar = range[1];
    }

    /** Eye rays per image side sampled for the depth range. */
    static final int DEPTH_SAMPLES = 64;
    /** The percentiles of the hit distances drawn white and black. */
    static final double NEAR = 0.02;
    static final double FAR = 0.75;

    /**
     * The distances shown as white and black in depth mode: the 2nd and 75th percentiles of the
     * hit distances of a 64 x 64 grid of eye rays (the farthest quarter is black), so that a huge
     * ground (the radius-100 sphere of spheres.json) or a far wall does not squeeze everything
     * else into one grey; the scene's box when nothing is hit. The same for every thread (a fixed grid).
     */
    static double[] depthRange(Scene scene, Surface root) {
        double[] d = new double[DEPTH_SAMPLES * DEPTH_SAMPLES];
        int n = 0;
        IntersectionRecord rec = new IntersectionRecord();
        for (int j = 0; j < DEPTH_SAMPLES; j++) {
            for (int i = 0; i < DEPTH_SAMPLES; i++) {
                int x = (int) ((i + 0.5) * scene.width / DEPTH_SAMPLES);
                int y = (int) ((j + 0.5) * scene.height / DEPTH_SAMPLES);
                Ray r = scene.camera.rayThroughPixelCenter(Math.min(x, scene.width - 1), Math.min(y, scene.height - 1));
                rec.reset();
                if (root.intersect(rec, r)) {
                    double dist = rec.t * r.d.length();
                    if (Double.isFinite(dist)) {
                        d[n++] = dist;
                    }
                }
            }
        }
        if (n > 0) {
            java.util.Arrays.sort(d, 0, n);
            double near = d[(int) Math.floor(NEAR * (n - 1))];
            double far = d[(int) Math.ceil(FAR * (n - 1))];
            if (far > near) {
                return new double[] {near, far};
            }
            return new double[] {Math.max(0, near - 1), near + 1};
        }
        var box = root.boundingBox();
        double radius = box.isEmpty() ? 1 : box.extent().length() / 2;
        double center = box.isEmpty() ? 1 : box.centroid().minus(scene.camera.eye).length();
        return new double[] {Math.max(0, center - radius), center + radius};
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
        Vec3 v = ray.d.normalize().negate();
        Point at = new Point(hit.point, n, v, m, stats);
        if (!plan.lighting) {
            // No light can reach any point: the light loop is not run at all.
            Color L = at.ambient();
            return mode == Mode.SHADOWS ? Color.WHITE : L;
        }
        Color L = Shading.shade(at.point, scene.lights);
        at.finish();
        if (mode == Mode.SHADOWS) {
            return at.inFront == 0 ? Color.BLACK : Color.WHITE.times((double) at.visible / at.inFront);
        }
        return L;
    }

    /**
     * The framework's answers to the questions of the student's {@link Shading#shade}, as the plan
     * and the debug mode say: a shadow ray only where the plan traces one, terms left out of a
     * debug mode black, every step counted and told to the listener.
     */
    private final class Point implements ShadingPoint.Answers {
        final ShadingPoint point;
        final RenderStats stats;
        final boolean specular;
        int inFront;
        int visible;
        /** The light the loop looked at last, until it is shaded or found blocked (for traces). */
        PointLight pending;

        Point(Vec3 x, Vec3 n, Vec3 v, Material m, RenderStats stats) {
            this.point = new ShadingPoint(x, n, v, m, this);
            this.stats = stats;
            this.specular = plan.specular && (plan.bruteForce || m.hasSpecular())
                    && (mode == Mode.FULL || mode == Mode.SPECULAR);
        }

        Color ambient() {
            return ambient(point);
        }

        @Override
        public Color ambient(ShadingPoint at) {
            if (mode != Mode.FULL || !plan.ambient) {
                return Color.BLACK;
            }
            Color a = at.material.ka().times(scene.ambient);
            if (listener != null) {
                listener.ambient(a);
            }
            return a;
        }

        @Override
        public void lookedAt(ShadingPoint at, PointLight light, Vec3 l) {
            finish();
            pending = light;
            if (listener != null) {
                listener.light(light, l, at.n.dot(l));
            }
        }

        /** A light looked at and then neither tested nor shaded was skipped: behind the surface. */
        void finish() {
            if (pending != null && listener != null) {
                listener.skipped(pending, pending.position.equals(point.x)
                        ? "exactly at the point (no direction l): no diffuse, no specular"
                        : "behind the surface (n·l <= 0): no diffuse, no specular");
            }
            pending = null;
        }

        @Override
        public boolean visible(ShadingPoint at, PointLight light) {
            pending = null;
            inFront++;
            int i = indexOf(light);
            if (i >= 0 && plan.shadows[i]) {
                stats.shadowRays++;
                // A fresh scratch record for each shadow ray: nothing of an earlier ray (another
                // pixel's, or through the process boundary a guess's) reaches the student's code.
                scratch.reset();
                boolean blocked = Shadows.isShadowed(root, at.x, at.n, light, scratch);
                stats.intersectionTests += scratch.tests;
                scratch.tests = 0;
                if (listener != null) {
                    listener.shadow(light, blocked, scratch);
                }
                if (blocked) {
                    stats.shadowRaysBlocked++;
                    return false;
                }
            } else if (listener != null) {
                listener.noShadowRay(light);
            }
            visible++;
            return true;
        }

        @Override
        public Color diffuse(ShadingPoint at, PointLight light, Vec3 l) {
            pending = null;
            if (mode != Mode.FULL && mode != Mode.DIFFUSE) {
                return Color.BLACK;
            }
            Color d = at.material.diffuse(at.n, l, light.intensity);
            if (listener != null) {
                listener.diffuse(light, d);
            }
            return d;
        }

        @Override
        public Color specular(ShadingPoint at, PointLight light, Vec3 l) {
            pending = null;
            if (!specular) {
                return Color.BLACK;
            }
            stats.specularEvaluations++;
            Color sp = at.material.specular(at.n, l, at.v, light.intensity);
            if (listener != null) {
                listener.specular(light, sp);
            }
            return sp;
        }
    }

    private int indexOf(PointLight light) {
        for (int i = 0; i < scene.lights.size(); i++) {
            if (scene.lights.get(i) == light) {
                return i;
            }
        }
        return -1;
    }

    /** n turned to face the incoming ray: −n when the ray hits the back side (d·n &gt; 0). */
    public static Vec3 facing(Vec3 n, Vec3 d) {
        return n.dot(d) > 0 ? n.negate() : n;
    }
}
