package raylab.surface;

import java.util.ArrayList;
import java.util.List;

import raylab.material.BlinnPhong;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.shading.Shading;
import raylab.shading.ShadingPoint;
import raylab.shading.Shadows;

/**
 * A hostile submission for the process boundary (BoundaryGradeTest): it implements nothing and
 * reports, in the message of every failing test, which secrets its process can reach: a
 * reference solution of another milestone (a graded method that runs instead of throwing the
 * stub's NotImplemented), a second Sphere class file (the reference), hidden tests, grader
 * classes, reference images.
 */
public class Sphere extends Surface {
    public final Vec3 center;
    public final double radius;

    public Sphere(Vec3 center, double radius, Material material, String name) {
        super(material, name);
        this.center = center;
        this.radius = radius;
    }

    static String probe() {
        List<String> found = new ArrayList<>();
        Vec3 o = new Vec3(0, 0, 0);
        Vec3 z = new Vec3(0, 0, 1);
        Ray ray = new Ray(new Vec3(0.1, 0.1, -5), z);
        tryRun(found, "Box.intersect", () -> new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), null, "b")
                .intersect(new IntersectionRecord(), ray));
        tryRun(found, "Triangle.intersect", () -> new Triangle(new Vec3(-1, -1, 0), new Vec3(1, -1, 0),
                new Vec3(0, 1, 0), null, "t").intersect(new IntersectionRecord(), ray));
        tryRun(found, "Lambertian.diffuse", () -> new Lambertian(new Color(1, 1, 1), Color.BLACK, "l")
                .diffuse(z, z, new Color(1, 1, 1)));
        tryRun(found, "BlinnPhong.specular", () -> new BlinnPhong(new Color(1, 1, 1), new Color(1, 1, 1), 10,
                Color.BLACK, "p").specular(z, z, z, new Color(1, 1, 1)));
        tryRun(found, "Shading.shade", () -> Shading.shade(ShadingPoint.plain(o, z, z,
                new Lambertian(new Color(1, 1, 1), Color.BLACK, "l"), Color.BLACK, l -> true), List.of()));
        tryRun(found, "Shadows.isShadowed", () -> Shadows.isShadowed(new Group(List.of(), null), o, z,
                new raylab.light.PointLight(z, new Color(1, 1, 1), true, "l"), new IntersectionRecord()));
        for (String c : List.of("raylab.surface.SphereHiddenTest", "raylab.surface.SphereTest",
                "raylab.cases.SphereCasesTest", "raylab.hidden.RenderMany", "raylab.grade.Grader",
                "raylab.numerics.Oracle", "raylab.numerics.SphereMethods", "raylab.course.SolutionRegions")) {
            try {
                Class.forName(c);
                found.add("class " + c);
            } catch (Throwable e) {
                // not there: good
            }
        }
        ClassLoader cl = Sphere.class.getClassLoader();
        try {
            int spheres = java.util.Collections.list(cl.getResources("raylab/surface/Sphere.class")).size();
            if (spheres != 1) {
                found.add(spheres + " Sphere class files");
            }
        } catch (java.io.IOException e) {
            found.add("getResources failed");
        }
        for (String r : List.of("scenes/reference/sphere.png", "reference/sphere.png", "expected.json")) {
            if (cl.getResource(r) != null || java.nio.file.Files.exists(java.nio.file.Path.of(r))) {
                found.add("resource " + r);
            }
        }
        return found.isEmpty() ? "PROBE found nothing" : "PROBE FOUND " + String.join(", ", found);
    }

    private static void tryRun(List<String> found, String what, Runnable r) {
        try {
            r.run();
            found.add("a working " + what);
        } catch (raylab.course.NotImplemented e) {
            // the stub: good
        } catch (Throwable e) {
            found.add(what + " threw " + e.getClass().getSimpleName());
        }
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        throw new IllegalStateException(probe());
    }

    @Override
    public BoundingBox boundingBox() {
        Vec3 r = new Vec3(radius, radius, radius);
        return new BoundingBox(center.minus(r), center.plus(r));
    }
}
