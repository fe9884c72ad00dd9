package raylab.inspect;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.render.Image;

/**
 * The feedback on a scene that differs, for the graded feedback: the worst pixels (largest
 * 8-bit difference between the student's render and the reference's), each traced both ways, the
 * first difference of each, and the most common first difference among them. Computed in the
 * grader's trusted render process ({@code raylab.boundary.TrustedRender}), where the student's
 * trees come through the process boundary and the reference's from the milestone's reference;
 * written as JSON ({@link #write}) for the grader's report ({@code raylab.grade.PixelFeedback}).
 */
public final class WorstPixels {
    /** Pixels traced both ways, at most; the worst {@link #SHOWN} of them are shown with their trees. */
    public static final int TRACED = 48;
    public static final int SHOWN = 3;

    /** Both ray trees of a pixel: {mine, reference}; null when either cannot be traced. */
    public interface Trees {
        RayTree[] at(int x, int y);
    }

    /** One pixel: where, its image difference, its first difference and both trees as rows. */
    public record Pixel(int x, int y, int imageDifference, FirstDifference.Difference difference,
            List<TreeTable.Row> rows) {
    }

    /** The most common first difference ({@code count} of {@code traced} pixels) and the pixels to show. */
    public record Result(String summary, int count, int traced, List<Pixel> shown) {
    }

    private WorstPixels() {
    }

    /**
     * Empty when the images agree everywhere or no traced pixel's trees differ. {@code scene}: the
     * student's (its surfaces answer single-surface questions, {@link FirstDifference#of}), or null.
     */
    public static Optional<Result> find(Image mine, Image reference, Trees trees, raylab.scene.Scene scene) {
        int w = mine.width;
        int h = mine.height;
        List<long[]> order = new ArrayList<>();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int d = difference(mine.get(x, y), reference.get(x, y));
                if (d > raylab.render.ImageCompare.PIXEL_THRESHOLD) {
                    order.add(new long[] {d, y * (long) w + x});
                }
            }
        }
        order.sort((a, b) -> a[0] != b[0] ? Long.compare(b[0], a[0]) : Long.compare(a[1], b[1]));
        List<Pixel> found = new ArrayList<>();
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (int i = 0; i < Math.min(TRACED, order.size()); i++) {
            int x = (int) (order.get(i)[1] % w);
            int y = (int) (order.get(i)[1] / w);
            RayTree[] t = trees.at(x, y);
            if (t == null) {
                continue;
            }
            Optional<FirstDifference.Difference> d = FirstDifference.of(t[0], t[1], scene);
            if (d.isEmpty()) {
                continue;
            }
            counts.merge(key(d.get()), 1, Integer::sum);
            found.add(new Pixel(x, y, (int) order.get(i)[0], d.get(), TreeTable.rows(t[0], t[1], d)));
        }
        if (found.isEmpty()) {
            return Optional.empty();
        }
        String common = counts.entrySet().stream().max(Map.Entry.comparingByValue()).orElseThrow().getKey();
        int n = counts.get(common);
        Pixel example = found.stream().filter(p -> key(p.difference()).equals(common)).findFirst().orElseThrow();
        String summary = "the most common first difference at the " + found.size() + " worst pixels traced: "
                + common + " (" + n + " of " + found.size() + "), for example at pixel (" + example.x() + ", "
                + example.y() + "): " + example.difference().line();
        return Optional.of(new Result(summary, n, found.size(), found.subList(0, Math.min(SHOWN, found.size()))));
    }

    /**
     * Whether {@link #find} has a pixel to trace: one whose 8-bit colours differ by more than
     * {@code ImageCompare.PIXEL_THRESHOLD}. The grader asks first, so that two images that agree
     * cost no student process for their feedback.
     */
    public static boolean anyDiffers(Image mine, Image reference) {
        for (int y = 0; y < mine.height; y++) {
            for (int x = 0; x < mine.width; x++) {
                if (difference(mine.get(x, y), reference.get(x, y)) > raylab.render.ImageCompare.PIXEL_THRESHOLD) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The largest 8-bit channel difference of two pixels (0 at once when their values are equal). */
    private static int difference(raylab.math.Color a, raylab.math.Color b) {
        if (a.r == b.r && a.g == b.g && a.b == b.b) {
            return 0;
        }
        return Inspection.channelDifference(Image.toRgb8(a), Image.toRgb8(b));
    }

    /** "Sphere.intersect, eye ray": what is counted as the same first difference. */
    static String key(FirstDifference.Difference d) {
        return d.method() + ", " + d.quantity();
    }

    private static final ObjectMapper JSON = new ObjectMapper();

    /** Writes the result as JSON (summary, counts, and per pixel x, y, difference, method, rows). */
    public static void write(Result r, Path file) throws IOException {
        ObjectNode o = JSON.createObjectNode();
        o.put("summary", r.summary());
        o.put("count", r.count());
        o.put("traced", r.traced());
        ArrayNode px = o.putArray("pixels");
        for (Pixel p : r.shown()) {
            ObjectNode n = px.addObject();
            n.put("x", p.x());
            n.put("y", p.y());
            n.put("imageDifference", p.imageDifference());
            n.put("difference", p.difference().line());
            n.put("method", p.difference().method());
            TreeTable.json(p.rows(), n.putArray("rows"));
        }
        Files.writeString(file, JSON.writeValueAsString(o));
    }
}
