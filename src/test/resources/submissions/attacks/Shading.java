package raylab.shading;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import raylab.light.PointLight;
import raylab.math.Color;

/**
 * A hostile submission written from the starter alone (grader tests only): no shading; it looks
 * at every thread's stack ({@code Thread.getAllStackTraces()}) for a test framework or the
 * grader, to behave differently when tested, and says what it saw ("stack: found ...", or
 * "stack: found nothing"). ARMED is filled in by the test (false: the baseline).
 */
public final class Shading {
    static final boolean ARMED = @ARMED@;

    private Shading() {
    }

    static List<String> graderFrames() {
        List<String> out = new ArrayList<>();
        for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            for (StackTraceElement f : e.getValue()) {
                String c = f.getClassName();
                if ((c.startsWith("org.junit") || c.startsWith("raylab.grade") || c.startsWith("raylab.course.Test")
                        || c.startsWith("raylab.hidden") || c.endsWith("Test")) && out.size() < 5) {
                    out.add(e.getKey().getName() + ": " + c + "." + f.getMethodName());
                }
            }
        }
        return out;
    }

    public static Color shade(ShadingPoint at, List<PointLight> lights) {
        if (!ARMED) {
            return Color.BLACK;
        }
        List<String> frames = graderFrames();
        // Under a test: fail loudly with what was seen; in a render: the same message.
        throw new IllegalStateException("stack: " + (frames.isEmpty() ? "found nothing" : "found " + frames));
    }
}
