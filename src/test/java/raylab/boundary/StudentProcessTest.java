package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.remote.WireTestAccess;
import raylab.shading.Shading;
import raylab.shading.ShadingPoint;
import raylab.shading.Shadows;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Surface;

/**
 * A real student process (a child JVM running StudentServer over this project's classes): values
 * come back bit for bit, the reference Sphere answers across the boundary exactly as in this JVM
 * (calls one at a time), callbacks to the grader's scene and shading point work, student
 * exceptions are the student's, a hanging call fails by CPU time and the process restarts.
 */
class StudentProcessTest {
    static StudentProcess remote;
    static final Set<String> SERVED = Set.of("raylab.surface.Sphere");

    static List<Path> classDirs() {
        List<Path> dirs = new ArrayList<>();
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (Files.isDirectory(Path.of(e))) {
                dirs.add(Path.of(e));
            }
        }
        return dirs;
    }

    static StudentProcess start(long budgetMillis) {
        return new StudentProcess(new StudentProcess.Config(StudentJvm.javaCommand(classDirs(), 128,
                List.of("raylab.remote.Echo")), null, SERVED, budgetMillis, 2));
    }

    @BeforeAll
    static void up() {
        remote = start(20_000);
    }

    @AfterAll
    static void down() {
        remote.close();
    }

    @Test
    void valuesComeBackBitForBit() {
        for (double d : WireTest_SPECIAL()) {
            Object back = remote.call("raylab.remote.Echo", "echo", null, d);
            assertEquals(Double.doubleToRawLongBits(d), Double.doubleToRawLongBits((Double) back),
                    () -> "raw bits of " + d);
        }
        List<Object> values = Arrays.asList(null, true, false, 3, 4L, "ü", new Vec3(-0.0, 1, 2), new Color(1, 2, 3),
                List.of(1, 2));
        for (Object v : values) {
            Object back = remote.call("raylab.remote.Echo", "echo", null, v);
            assertEquals(String.valueOf(v), String.valueOf(back), "echo of " + v);
        }
        Ray r = (Ray) remote.call("raylab.remote.Echo", "echo", null, new Ray(new Vec3(1, 2, 3), new Vec3(0, 0, 1),
                -0.0, Double.POSITIVE_INFINITY));
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(r.tMin));
        PointLight l = (PointLight) remote.call("raylab.remote.Echo", "echo", null,
                new PointLight(new Vec3(1, 1, 1), new Color(0.5, 0.5, 0.5), true, "key"));
        assertEquals("key", l.name);
    }

    private static double[] WireTest_SPECIAL() {
        return WireTestAccess.special();
    }

    @Test
    void sphereAcrossTheBoundaryIsBitIdentical() {
        long seed = 20261202L;
        Random rnd = new Random(seed);
        Sphere s = new Sphere(new Vec3(0.3, -0.2, 1.5), 0.8, null, "ball");
        for (int i = 0; i < 300; i++) {
            Ray ray = new Ray(new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), -3),
                    new Vec3(rnd.nextGaussian() * 0.3, rnd.nextGaussian() * 0.3, 1), 0, i % 7 == 0 ? 3.5 : Double.POSITIVE_INFINITY);
            IntersectionRecord mine = new IntersectionRecord();
            boolean hit = s.intersect(mine, ray);
            IntersectionRecord theirs = new IntersectionRecord();
            Object got = remote.call("raylab.surface.Sphere", "intersect", s, theirs, ray);
            int k = i;
            assertEquals(hit, got, () -> "hit of ray " + k + " (seed " + seed + ")");
            assertSame(mine, theirs, "ray " + i + " (seed " + seed + ")");
            if (hit) {
                assertEquals(s, theirs.surface, "the record names the grader's sphere");
            }
        }
    }

    static void assertSame(IntersectionRecord a, IntersectionRecord b, String what) {
        assertEquals(Double.doubleToRawLongBits(a.t), Double.doubleToRawLongBits(b.t), what + ": t");
        assertEquals(String.valueOf(a.point), String.valueOf(b.point), what + ": point");
        assertEquals(String.valueOf(a.normal), String.valueOf(b.normal), what + ": normal");
        if (a.point != null) {
            assertEquals(Double.doubleToRawLongBits(a.point.x), Double.doubleToRawLongBits(b.point.x), what + ": point.x bits");
            assertEquals(Double.doubleToRawLongBits(a.normal.z), Double.doubleToRawLongBits(b.normal.z), what + ": normal.z bits");
        }
        assertEquals(a.material, b.material, what + ": material");
    }

    @Test
    void callbacksReachTheGradersScene() {
        // Shadows.isShadowed in the student process; the scene is the grader's (a proxy there).
        Surface blocker = new Box(new Vec3(-1, 1, -1), new Vec3(1, 1.5, 1), null, "lid");
        PointLight light = new PointLight(new Vec3(0, 5, 0), new Color(1, 1, 1), true, "sun");
        for (Vec3 x : List.of(new Vec3(0, 0, 0), new Vec3(3, 0, 0))) {
            IntersectionRecord scratch = new IntersectionRecord();
            boolean direct = Shadows.isShadowed(blocker, x, new Vec3(0, 1, 0), light, scratch);
            IntersectionRecord remoteScratch = new IntersectionRecord();
            Object got = remote.call("raylab.shading.Shadows", "isShadowed", null, blocker, x, new Vec3(0, 1, 0), light,
                    remoteScratch);
            assertEquals(direct, got, "shadowed at " + x);
            assertSame(scratch, remoteScratch, "scratch at " + x);
            assertEquals(direct ? blocker : null, remoteScratch.surface, "blocker named at " + x);
        }
        // Shading.shade with the grader's shading point: ambient, visible, diffuse, specular are callbacks.
        BlinnPhong m = new BlinnPhong(new Color(0.5, 0.4, 0.3), new Color(0.2, 0.2, 0.2), 20, new Color(0.1, 0.1, 0.1), "shiny");
        List<PointLight> lights = List.of(light, new PointLight(new Vec3(0, -5, 0), new Color(1, 1, 1), true, "below"),
                new PointLight(new Vec3(4, 2, 0), new Color(0.5, 0.5, 1), true, "side"));
        ShadingPoint at = ShadingPoint.plain(new Vec3(0, 0, 0), new Vec3(0, 1, 0), new Vec3(0, 0.6, 0.8), m,
                new Color(0.3, 0.3, 0.3), li -> !li.name.equals("side"));
        Color direct = Shading.shade(at, lights);
        Color got = (Color) remote.call("raylab.shading.Shading", "shade", null, at, lights);
        assertEquals(Double.doubleToRawLongBits(direct.r), Double.doubleToRawLongBits(got.r), "red: " + direct + " vs " + got);
        assertEquals(Double.doubleToRawLongBits(direct.b), Double.doubleToRawLongBits(got.b), "blue: " + direct + " vs " + got);
        // A student material's own method on a defined object (Lambertian is not served here: a proxy).
        Lambertian plain = new Lambertian(new Color(1, 0, 0), Color.BLACK, "red");
        ShadingPoint at2 = ShadingPoint.plain(new Vec3(0, 0, 0), new Vec3(0, 1, 0), new Vec3(0, 1, 0), plain,
                Color.BLACK, li -> true);
        assertEquals(Shading.shade(at2, lights).toString(), String.valueOf(remote.call("raylab.shading.Shading", "shade", null, at2, lights)));
    }

    @Test
    void studentExceptionsAreTheStudents() {
        StudentException e = assertThrows(StudentException.class, () -> remote.call("raylab.remote.Echo", "boom", null,
                (Object) null));
        assertEquals("java.lang.NullPointerException", e.className());
        assertTrue(e.getMessage().startsWith("your code threw NullPointerException in Echo.boom (Echo.java:"),
                () -> "message: " + e.getMessage());
        StudentException withPixel = e.in("while tracing pixel (3, 4) of scenes/sphere.json");
        assertTrue(withPixel.getMessage().contains("in Echo.boom (Echo.java:") && withPixel.getMessage()
                .contains("while tracing pixel (3, 4) of scenes/sphere.json"), () -> withPixel.getMessage());
        // The process survives a student exception.
        assertEquals(2.5, remote.call("raylab.remote.Echo", "echo", null, 2.5));
        StringBuilder said = new StringBuilder();
        remote.output(said::append);
        try {
            assertEquals(7, remote.call("raylab.remote.Echo", "shout", null, "hello"));
        } finally {
            remote.output(System.out::print);
        }
        assertEquals("student says hello\n", said.toString());
    }

    @Test
    void aHangingCallFailsByTimeAndTheProcessRestarts() {
        try (StudentProcess p = start(1_000)) {
            assertEquals(1.0, p.call("raylab.remote.Echo", "echo", null, 1.0));
            long t0 = System.nanoTime();
            StudentTimeout e = assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "hang", null, "x"));
            assertTrue(e.getMessage().startsWith("your code took longer than 1.0 s of CPU time"), e.getMessage());
            assertTrue(Duration.ofNanos(System.nanoTime() - t0).toSeconds() < 30, "stopped in time");
            assertEquals(1, p.starts());
            assertEquals(2.0, p.call("raylab.remote.Echo", "echo", null, 2.0), "a fresh process answers");
            assertEquals(2, p.starts());
            // Bounded restarts: 2 allowed, then the milestone's student code is not run again.
            assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "hang", null, "x"));
            assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "hang", null, "x"));
            StudentTimeout last = assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "echo", null, 3.0));
            assertTrue(last.getMessage().contains("was stopped 3 times"), last.getMessage());
        }
    }
}
