package raylab.oracle;

import java.util.List;

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
import raylab.surface.Surface;

/** Text traces of one pixel as the reference renders it, and the tie check of the brute force test. */
final class ReferenceTrace {
    private ReferenceTrace() {
    }

    /** The reference's steps for pixel (x, y) under the given plan. */
    static String of(Scene scene, RenderPlan plan, int x, int y) {
        StringBuilder sb = new StringBuilder();
        Renderer renderer = new Renderer(scene, plan, Mode.FULL);
        Shader shader = new Shader(scene, renderer.root(), plan, Mode.FULL);
        shader.listen(new ShadeListener() {
            @Override
            public void normal(Vec3 outward, Vec3 facing) {
                sb.append("\n      outward normal ").append(outward).append(", facing the viewer ").append(facing);
            }

            @Override
            public void ambient(Color term) {
                sb.append("\n      ambient ka·Ia = ").append(term);
            }

            @Override
            public void light(PointLight light, Vec3 l, double nDotL) {
                sb.append("\n      light '").append(light.name).append("': l = ").append(l).append(", n·l = ").append(nDotL);
            }

            @Override
            public void shadow(PointLight light, boolean blocked, IntersectionRecord blocker) {
                sb.append("\n        shadow ray: ").append(blocked ? "blocked by " + blocker : "not blocked");
            }

            @Override
            public void skipped(PointLight light, String why) {
                sb.append("\n        skipped: ").append(why);
            }

            @Override
            public void noShadowRay(PointLight light) {
                sb.append("\n        no shadow ray (plan)");
            }

            @Override
            public void diffuse(PointLight light, Color term) {
                sb.append("\n        diffuse ").append(term);
            }

            @Override
            public void specular(PointLight light, Color term) {
                sb.append("\n        specular ").append(term);
            }
        });
        IntersectionRecord rec = new IntersectionRecord();
        Ray ray = scene.camera.rayThroughPixelCenter(x, y);
        Color c = renderer.pixel(x, y, shader, rec, new RenderStats());
        return "    eye ray " + ray + "\n      " + rec + sb + "\n      = " + c;
    }

    /**
     * Whether the eye ray of pixel (x, y) has an exact tie: two or more primitives hit at the
     * same smallest t, so that which one wins depends on the order they are tested in.
     */
    static boolean tie(Scene scene, int x, int y) {
        Ray ray = scene.camera.rayThroughPixelCenter(x, y);
        List<Surface> prims = RenderPlan.primitives(scene.surfaces);
        double best = Double.POSITIVE_INFINITY;
        int count = 0;
        for (Surface s : prims) {
            IntersectionRecord rec = new IntersectionRecord();
            if (s.intersect(rec, ray)) {
                if (rec.t < best) {
                    best = rec.t;
                    count = 1;
                } else if (rec.t == best) {
                    count++;
                }
            }
        }
        return count >= 2;
    }
}
