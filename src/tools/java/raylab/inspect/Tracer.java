package raylab.inspect;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.ShadeListener;
import raylab.render.Shader;
import raylab.scene.Scene;

/**
 * Traces pixels of a scene through the code on the class path (the student's, or at release time
 * the reference solution) and records their {@link RayTree}s, as {@code raylab trace} prints them.
 */
public final class Tracer {
    private final Scene scene;
    private final Renderer renderer;
    private final Shader shader;

    public Tracer(Scene scene) {
        this.scene = scene;
        RenderPlan plan = new RenderPlan(scene);
        this.renderer = new Renderer(scene, plan, Mode.FULL);
        this.shader = new Shader(scene, renderer.root(), plan, Mode.FULL);
    }

    public Scene scene() {
        return scene;
    }

    public Renderer renderer() {
        return renderer;
    }

    /** The ray tree of the ray through the centre of pixel (x, y). */
    public RayTree trace(int x, int y) {
        Ray ray = scene.camera.rayThroughPixelCenter(x, y);
        RayTree tree = new RayTree(x, y, ray.p, ray.d);
        for (PointLight l : scene.lights) {
            tree.light(l.name);
        }
        IntersectionRecord hit = new IntersectionRecord();
        if (!renderer.root().intersect(hit, ray)) {
            tree.colour = scene.background;
            return tree;
        }
        tree.surface = hit.surface == null ? "?" : hit.surface.name();
        tree.kind = kindOf(hit.surface);
        tree.t = hit.t;
        tree.point = hit.point;
        tree.normal = hit.normal;
        tree.lit = hit.material != null && hit.material.isLit();
        shader.listen(new Listener(tree));
        try {
            tree.colour = shader.shade(ray, hit, new RenderStats());
        } finally {
            shader.listen(null);
        }
        return tree;
    }

    /** Sphere, Box, Triangle, ... : the class whose intersect computed the hit. */
    static String kindOf(Object surface) {
        return surface == null ? "Surface" : surface.getClass().getSimpleName();
    }

    /** Fills a tree from the shader's steps. */
    private static final class Listener implements ShadeListener {
        private final RayTree tree;

        Listener(RayTree tree) {
            this.tree = tree;
        }

        @Override
        public void ambient(Color term) {
            tree.ambient = tree.ambient == null ? term : tree.ambient.plus(term);
            tree.ambientAdded++;
        }

        @Override
        public void light(PointLight light, Vec3 l, double nDotL) {
            RayTree.Light t = tree.light(light.name);
            if (t.state == RayTree.State.NOT_LOOKED) {
                t.state = RayTree.State.BEHIND; // until a shadow test says otherwise
            }
        }

        @Override
        public void noShadowRay(PointLight light) {
            tree.light(light.name).state = RayTree.State.NO_SHADOW_RAY;
        }

        @Override
        public void shadow(PointLight light, boolean blocked, IntersectionRecord blocker) {
            RayTree.Light t = tree.light(light.name);
            t.state = blocked ? RayTree.State.BLOCKED : RayTree.State.CLEAR;
            if (blocked) {
                t.blocker = blocker.surface == null ? "?" : blocker.surface.name();
                t.blockerT = blocker.t;
            }
        }

        @Override
        public void diffuse(PointLight light, Color term) {
            RayTree.Light t = tree.light(light.name);
            t.diffuse = t.diffuse == null ? term : t.diffuse.plus(term);
        }

        @Override
        public void specular(PointLight light, Color term) {
            RayTree.Light t = tree.light(light.name);
            t.specular = t.specular == null ? term : t.specular.plus(term);
        }
    }
}
