package raylab.grade.platform;

import java.awt.Image;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.grade.GradeReport;

/**
 * PrairieLearn's external-grading {@code results.json}, written from a {@link GradeReport}: the
 * score as a fraction in [0, 1], {@code gradable: false} when a graded milestone does not compile
 * or the grading failed, a part of it included ({@link GradeReport#failed()}: PrairieLearn then
 * records no score and does not charge the student an attempt), one entry of {@code tests[]} per
 * graded item with {@code points}, {@code max_points} and the message in the student's terms, and
 * each scene's render, reference and difference as {@code images} (PNG data URIs). The file stays
 * under PrairieLearn's limit of 1 MB: images are halved in size until it fits, then dropped.
 *
 * <p>The grade of record includes the hidden items (visibility other than {@code visible}) at
 * every grading: PrairieLearn's assessment regrade only recomputes stored scores and never runs an
 * external grader again (PrairieLearn's {@code docs/assessment/regrading.md}), so hidden tests
 * graded "later" would never count for on-time work. Before the due date (and always, without
 * one) they are shown as one row per milestone, "hidden tests and data cases", with their points
 * and maximum only: no name, message, output or note of a hidden item. After the due date (a new
 * submission or a grading job run again by the staff) each hidden item has its own row.
 */
public final class PrairieLearn {
    /** PrairieLearn rejects a results file of more than 1 MB. */
    public static final int LIMIT_BYTES = 1_000_000;

    private static final ObjectMapper JSON = new ObjectMapper();

    /** The name (after "MILESTONE: ") of the row that totals a milestone's hidden items before the due date. */
    public static final String HIDDEN_ROW = "hidden tests and data cases (total)";

    private PrairieLearn() {
    }

    /** Whether any graded milestone failed to compile: PrairieLearn should not charge an attempt. */
    public static boolean compileError(GradeReport r) {
        return r.milestones().stream().flatMap(m -> m.notes().stream()).anyMatch(n -> n.contains("does not compile"));
    }

    private static boolean shown(GradeReport.Test t, boolean afterDueDate) {
        return afterDueDate || "visible".equals(t.visibility());
    }

    /** The results.json text, under {@code limit} bytes (UTF-8). */
    public static String results(GradeReport r, boolean afterDueDate, int limit) throws IOException {
        int[] widths = {0, 480, 240, 120, -1};
        String json = "";
        for (int w : widths) {
            json = JSON.writeValueAsString(tree(r, afterDueDate, w));
            if (json.getBytes(StandardCharsets.UTF_8).length <= limit) {
                return json;
            }
        }
        // Even without images too long (an enormous output): cut every test's output.
        Map<String, Object> root = tree(r, afterDueDate, -1);
        for (Object o : (List<?>) root.get("tests")) {
            @SuppressWarnings("unchecked")
            Map<String, Object> t = (Map<String, Object>) o;
            t.put("output", "");
        }
        root.put("output", "");
        return JSON.writeValueAsString(root);
    }

    /** The same with PrairieLearn's limit. */
    public static String results(GradeReport r, boolean afterDueDate) throws IOException {
        return results(r, afterDueDate, LIMIT_BYTES);
    }

    /**
     * @param maxWidth 0: images as rendered; > 0: at most this many pixels wide; -1: no images
     */
    static Map<String, Object> tree(GradeReport r, boolean afterDueDate, int maxWidth) throws IOException {
        if (r.failed()) {
            // PrairieLearn's way to say that no grade was decided: not gradable (no attempt charged,
            // no score recorded), with the message; the cause is in the grader's log for the staff.
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("gradable", false);
            root.put("score", 0.0);
            root.put("message", GradeReport.FAILED_FOR_STUDENTS);
            root.put("output", "");
            root.put("tests", List.of());
            return root;
        }
        double score = 0;
        double max = 0;
        int hiddenLeftOut = 0;
        List<Map<String, Object>> tests = new ArrayList<>();
        for (GradeReport.Milestone m : r.milestones()) {
            double hiddenPoints = 0;
            double hiddenMax = 0;
            int hiddenCount = 0;
            for (GradeReport.Test t : m.tests()) {
                if (!shown(t, afterDueDate)) {
                    // Graded now and counted; shown only as the milestone's total below.
                    hiddenLeftOut++;
                    hiddenCount++;
                    hiddenPoints += t.score();
                    hiddenMax += t.maxScore();
                    continue;
                }
                score += t.score();
                max += t.maxScore();
                Map<String, Object> j = new LinkedHashMap<>();
                j.put("name", m.id() + ": " + t.name());
                j.put("description", description(m, t));
                j.put("points", round(t.score()));
                j.put("max_points", round(t.maxScore()));
                String message = t.passed() ? "" : t.message();
                if (t.images() != null && !t.images().metric().isEmpty()) {
                    message = message.isEmpty() ? t.images().metric() : message + "\n" + t.images().metric();
                }
                j.put("message", message);
                j.put("output", t.kind() == GradeReport.Kind.HIDDEN ? "" : t.output());
                if (t.images() != null && maxWidth >= 0) {
                    List<Map<String, String>> images = new ArrayList<>();
                    add(images, "your render", t.images().student(), maxWidth);
                    add(images, "reference", t.images().reference(), maxWidth);
                    add(images, "difference", t.images().diff(), maxWidth);
                    j.put("images", images);
                }
                tests.add(j);
            }
            if (hiddenCount > 0) {
                score += hiddenPoints;
                max += hiddenMax;
                Map<String, Object> j = new LinkedHashMap<>();
                j.put("name", m.id() + ": " + HIDDEN_ROW);
                j.put("description", hiddenCount + " hidden item" + (hiddenCount == 1 ? "" : "s") + " of " + m.title()
                        + ", graded now and counted in the score; which passed and their messages are withheld");
                j.put("points", round(hiddenPoints));
                j.put("max_points", round(hiddenMax));
                j.put("message", "");
                j.put("output", "");
                tests.add(j);
            }
        }
        Map<String, Object> root = new LinkedHashMap<>();
        boolean gradable = !compileError(r);
        root.put("gradable", gradable);
        root.put("score", max > 0 ? Math.max(0, Math.min(1, score / max)) : 0.0);
        StringBuilder msg = new StringBuilder();
        msg.append(String.format(Locale.ROOT, "raylab: %s / %s points", fmt(score), fmt(max)));
        if (hiddenLeftOut > 0) {
            msg.append(" (the hidden tests and data cases included: their total is shown, their names and messages are"
                    + " withheld)");
        }
        msg.append('.');
        for (GradeReport.Milestone m : r.milestones()) {
            for (String n : m.notes()) {
                // A note about the hidden run (it did not finish) is hidden information too.
                if (afterDueDate || !n.toLowerCase(Locale.ROOT).contains("hidden")) {
                    msg.append('\n').append(m.id()).append(": ").append(n);
                }
            }
        }
        if (!gradable) {
            msg.append("\nThis submission does not compile: it was not counted as an attempt. Fix the error and submit again.");
        }
        if (r.milestones().isEmpty()) {
            r.studentNotes().forEach(n -> msg.append('\n').append(n));
        }
        root.put("message", msg.toString());
        StringBuilder out = new StringBuilder();
        if (!r.accepted().isEmpty()) {
            out.append("Graded files:\n");
            r.accepted().forEach(a -> out.append("  ").append(a).append('\n'));
        }
        if (!r.ignored().isEmpty()) {
            out.append("Ignored (only the assignment's files are graded): ").append(r.ignored().size()).append(" file(s)\n");
        }
        root.put("output", out.toString());
        root.put("tests", tests);
        return root;
    }

    private static String description(GradeReport.Milestone m, GradeReport.Test t) {
        return switch (t.kind()) {
            case VISIBLE -> "visible test of " + m.title() + " (you can run it: ./raylab check " + m.id() + ")";
            case HIDDEN -> "hidden test of " + m.title();
            case CASE -> "data case of " + m.title();
            case SCENE -> "scene of " + m.title() + ", compared with the reference image";
        };
    }

    private static void add(List<Map<String, String>> images, String label, byte[] png, int maxWidth) throws IOException {
        if (png == null || png.length == 0) {
            return;
        }
        images.add(Map.of("label", label, "url", "data:image/png;base64,"
                + Base64.getEncoder().encodeToString(maxWidth > 0 ? shrink(png, maxWidth) : png)));
    }

    /** The PNG scaled down to at most {@code width} pixels wide (unchanged if it is narrower). */
    static byte[] shrink(byte[] png, int width) throws IOException {
        BufferedImage img = ImageIO.read(new ByteArrayInputStream(png));
        if (img == null || img.getWidth() <= width) {
            return png;
        }
        int h = Math.max(1, (int) Math.round(img.getHeight() * (double) width / img.getWidth()));
        BufferedImage small = new BufferedImage(width, h, BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = small.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.drawImage(img.getScaledInstance(width, h, Image.SCALE_AREA_AVERAGING), 0, 0, null);
        g.dispose();
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(small, "png", b);
        return b.toByteArray();
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }

    private static String fmt(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        return s.endsWith(".00") ? s.substring(0, s.length() - 3) : s;
    }
}
