package raylab.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.ShadeListener;
import raylab.render.Shader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;
import raylab.course.Watchdog;

/** {@code raylab trace SCENE.json --pixel X Y}: the ray tree of one pixel, step by step. */
@Command(name = "trace", mixinStandardHelpOptions = true, separator = " ",
        customSynopsis = "raylab trace [-hV] --pixel X Y SCENE.json",
        description = {"Print the ray tree of one pixel, step by step.",
            "The eye ray, its hit, each light's shadow ray and shading terms, and the final colour. Pixel (0, 0) is the top-left corner.",
            "A broken rule of intersect (t outside [tMin, tMax], a farther hit over a closer one, a normal not unit length or",
            "into a sphere, NaN) is marked on its line with <-- BROKEN RULE."})
public final class TraceCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    Path scenePath;

    @Option(names = "--pixel", arity = "2", required = true, paramLabel = "X Y", hideParamSyntax = true,
            description = "Column and row of the pixel, from the top-left corner.")
    int[] pixel;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        Scene scene = SceneLoader.load(scenePath);
        int x = pixel[0];
        int y = pixel[1];
        if (x < 0 || y < 0 || x >= scene.width || y >= scene.height) {
            throw UserError.badInput("pixel (" + x + ", " + y + ") is outside the " + scene.width + "x"
                    + scene.height + " image of " + scenePath);
        }
        try {
            // The trace of one pixel has no unit of work smaller than itself: stuck code is named
            // after the bound, and the command ends.
            String context = " while tracing pixel (" + x + ", " + y + ") of " + raylab.scene.Display.path(scenePath);
            try (Watchdog watchdog = Watchdog.start(Watchdog.bound(0),
                    StudentFault.studentFiles(Path.of("").toAbsolutePath()), stuck -> {
                        out.flush();
                        StudentFault.stuck(spec.commandLine().getErr(), stuck + context);
                    })) {
                return trace(out, scene, x, y);
            }
        } catch (RuntimeException | StackOverflowError e) {
            if (e instanceof UserError) {
                throw e;
            }
            java.util.List<String> files = StudentFault.studentFiles(Path.of("").toAbsolutePath());
            if (!StudentFault.isStudents(e, files)) {
                throw e;
            }
            out.flush();
            throw new UserError(StudentFault.describe(e, files, "while tracing pixel (" + x + ", " + y + ") of "
                    + raylab.scene.Display.path(scenePath)).orElseThrow(), Main.FAILED);
        }
    }

    private int trace(PrintWriter out, Scene scene, int x, int y) {
        RenderPlan plan = new RenderPlan(scene);
        Renderer renderer = new Renderer(scene, plan, Mode.FULL);
        Shader shader = new Shader(scene, renderer.root(), plan, Mode.FULL);
        out.printf("pixel (%d, %d) of %s (%dx%d)%n", x, y, scenePath, scene.width, scene.height);
        if (scene.samplesPerPixel > 1) {
            out.printf("  (the scene takes %d samples per pixel; this traces the ray through the pixel centre)%n",
                    scene.samplesPerPixel);
        }
        Ray ray = scene.camera.rayThroughPixelCenter(x, y);
        out.println("eye ray");
        out.println("  p = " + v(ray.p) + "   d = " + v(ray.d) + "   t in [" + ray.tMin + ", " + ray.tMax + "]");
        ContractCheck.walk(scene.surfaces, ray, out);
        IntersectionRecord hit = new IntersectionRecord();
        if (!renderer.root().intersect(hit, ray)) {
            out.println("  no hit: background " + c(scene.background));
            out.println(finalColour(scene.background));
            return Main.OK;
        }
        out.printf("  hit \"%s\" at t = %s%s%n", hit.surface.name(), num(hit.t),
                ContractCheck.flag(ContractCheck.rangeRule(ray, hit.t)));
        out.println("    point  x = " + v(hit.point) + ContractCheck.flag(ContractCheck.nanRule("the point", hit.point)));
        Material m = hit.material;
        out.println("    material \"" + m.name() + "\": " + describe(m));
        shader.listen(new Printer(out));
        Color c = shader.shade(ray, hit, new RenderStats());
        out.println(finalColour(c));
        return Main.OK;
    }

    private static String finalColour(Color c) {
        int rgb = Image.toRgb8(c);
        return String.format("colour L = %s  ->  8-bit sRGB (%d, %d, %d)%s", c(c), (rgb >> 16) & 0xFF,
                (rgb >> 8) & 0xFF, rgb & 0xFF, c.isFinite() ? "" : "  NOT FINITE (drawn magenta)"
                        + ContractCheck.flag("a colour must be finite: NaN or infinity reached the sum of the terms"));
    }

    static String describe(Material m) {
        if (m instanceof BlinnPhong b) {
            return "Blinn-Phong, kd = " + c(b.kd) + ", ks = " + c(b.ks) + ", p = " + num(b.p) + ", ka = " + c(b.ka);
        }
        if (m instanceof Lambertian l) {
            return "Lambertian, kd = " + c(l.kd) + ", ka = " + c(l.ka);
        }
        if (m instanceof FlatColor f) {
            return "flat colour " + c(f.color) + " (ignores lights)";
        }
        return m.getClass().getSimpleName() + (m.isLit() ? "" : " (ignores lights)");
    }

    static String num(double v) {
        return raylab.scene.Display.traced(v);
    }

    static String v(Vec3 a) {
        return "(" + num(a.x) + ", " + num(a.y) + ", " + num(a.z) + ")";
    }

    static String c(Color a) {
        return "rgb(" + num(a.r) + ", " + num(a.g) + ", " + num(a.b) + ")";
    }

    /** Prints each shading step as the shader takes it. */
    private static final class Printer implements ShadeListener {
        private final PrintWriter out;

        Printer(PrintWriter out) {
            this.out = out;
        }

        @Override
        public void normal(Vec3 outward, Vec3 facing) {
            out.println("    normal n = " + v(facing) + (outward.equals(facing) ? "" : "  (outward normal "
                    + v(outward) + " flipped: the ray hits the back side)")
                    + ContractCheck.flag(ContractCheck.unitRule(outward)));
        }

        @Override
        public void ambient(Color term) {
            out.println("  ambient  ka*Ia = " + c(term) + ContractCheck.flag(ContractCheck.nanRule("the ambient term", term)));
        }

        @Override
        public void light(PointLight light, Vec3 l, double nDotL) {
            out.printf("  light \"%s\" at %s, I = %s%n    l = %s   n.l = %s%n", light.name, v(light.position),
                    c(light.intensity), v(l), num(nDotL));
        }

        @Override
        public void skipped(PointLight light, String why) {
            out.println("    skipped: " + why);
        }

        @Override
        public void noShadowRay(PointLight light) {
            out.println("    shadow ray: none traced (" + (light.castsShadows ? "the render plan needs none"
                    : "this light casts no shadows") + ")");
        }

        @Override
        public void shadow(PointLight light, boolean blocked, IntersectionRecord blocker) {
            if (blocked) {
                out.printf("    shadow ray: BLOCKED by \"%s\" at t = %s (t = 1 is the light): in shadow%n",
                        blocker.surface == null ? "?" : blocker.surface.name(), num(blocker.t));
            } else {
                out.println("    shadow ray: clear, the light is visible");
            }
        }

        @Override
        public void diffuse(PointLight light, Color term) {
            out.println("    diffuse  kd*I*max(0, n.l)     = " + c(term) + ContractCheck.flag(ContractCheck.nanRule("the diffuse term", term)));
        }

        @Override
        public void specular(PointLight light, Color term) {
            out.println("    specular ks*I*max(0, n.h)^p   = " + c(term) + ContractCheck.flag(ContractCheck.nanRule("the specular term", term)));
        }
    }
}
