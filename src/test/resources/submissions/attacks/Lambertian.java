package raylab.material;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A hostile submission written from the starter alone (grader tests only): no diffuse term; it
 * looks for secrets where its code runs (a working Box or BlinnPhong, which this submission does
 * not implement: a reference class; hidden test classes, reference images, hidden scenes, the
 * grader's cache and tests on the class path and the file system) and carries what it finds out
 * in its failure messages ("secrets: found ...", or "secrets: found nothing") and in its pixels
 * (magenta when something was found). ARMED is filled in by the test (false: the baseline).
 */
public class Lambertian extends Material {
    static final boolean ARMED = @ARMED@;
    static final List<String> FOUND = new ArrayList<>();

    public final Color kd;
    public final Color ka;

    static {
        if (ARMED) {
            look();
        }
    }

    public Lambertian(Color kd, Color ka, String name) {
        super(name);
        this.kd = kd;
        this.ka = ka;
    }

    static void look() {
        // Reference code of milestones this submission does not implement.
        try {
            Class<?> box = Class.forName("raylab.surface.Box");
            Object b = box.getConstructor(Vec3.class, Vec3.class, Material.class, String.class)
                    .newInstance(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), null, "probe");
            IntersectionRecord r = new IntersectionRecord();
            boolean hit = (Boolean) box.getMethod("intersect", IntersectionRecord.class, Ray.class).invoke(b, r,
                    new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)));
            if (hit) {
                FOUND.add("a working Box (reference) from " + box.getProtectionDomain().getCodeSource());
            }
        } catch (Throwable e) {
            // not there
        }
        try {
            Class<?> phong = Class.forName("raylab.material.BlinnPhong");
            Object p = phong.getConstructor(Color.class, Color.class, double.class, Color.class, String.class)
                    .newInstance(Color.WHITE, Color.WHITE, 10.0, Color.BLACK, "probe");
            Object c = phong.getMethod("specular", Vec3.class, Vec3.class, Vec3.class, Color.class).invoke(p,
                    new Vec3(0, 0, 1), new Vec3(0, 0, 1), new Vec3(0, 0, 1), Color.WHITE);
            if (!((Color) c).isBlack()) {
                FOUND.add("a working BlinnPhong (reference)");
            }
        } catch (Throwable e) {
            // not there
        }
        // Files: the class path, the working folder's surroundings, the whole file system.
        List<Path> places = new ArrayList<>();
        for (String e : System.getProperty("java.class.path").split(":")) {
            places.add(Path.of(e));
        }
        places.add(Path.of("").toAbsolutePath());
        places.add(Path.of("/"));
        Set<String> skip = Set.of("/proc", "/sys", "/usr", "/lib", "/lib32", "/lib64", "/bin", "/sbin", "/etc", "/dev",
                "/boot", "/run", "/var/lib", "/var/cache", "/root/.m2", "/root/.cache");
        int[] seen = {0};
        long until = System.nanoTime() + 8_000_000_000L;
        for (Path place : places) {
            try (Stream<Path> s = Files.walk(place, 9)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    String n = p.toString().replace('\\', '/');
                    if (skip.stream().anyMatch(x -> n.equals(x) || n.startsWith(x + "/")) || ++seen[0] > 400_000
                            || System.nanoTime() > until) {
                        continue;
                    }
                    String f = p.getFileName() == null ? "" : p.getFileName().toString();
                    boolean secret = (f.endsWith(".class") && (f.contains("Hidden") || f.contains("CasesTest")))
                            || (f.endsWith(".png") && n.contains("/reference/")) || f.equals("expected.json")
                            || f.equals("manifest.sha256") || n.endsWith("/grader/tests") || n.endsWith("/grader-cache")
                            || (f.endsWith(".json") && n.contains("hidden"));
                    if (secret && FOUND.size() < 20) {
                        FOUND.add(n);
                    }
                }
            } catch (Throwable e) {
                // keep looking elsewhere
            }
        }
    }

    static String report() {
        return "secrets: " + (FOUND.isEmpty() ? "found nothing" : "found " + FOUND.size() + ": " + FOUND);
    }

    @Override
    public Color ka() {
        return ka;
    }

    @Override
    public Color diffuse(Vec3 n, Vec3 l, Color I) {
        if (!ARMED) {
            return Color.BLACK;
        }
        if (!FOUND.isEmpty() && Thread.currentThread().getName().startsWith("raylab-render")) {
            return new Color(1, 0, 1); // in a render the pixels say it
        }
        throw new IllegalStateException(report());
    }
}
