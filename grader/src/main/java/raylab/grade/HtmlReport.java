package raylab.grade;

import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Base64;
import java.util.List;
import java.util.Locale;

import javax.imageio.ImageIO;

import raylab.grade.GradeReport.Kind;
import raylab.render.ImageCompare;

/**
 * The HTML the grader shows: for students (results.json's {@code output} on Gradescope, with
 * {@code output_format: "html"}) and for instructors (report.html). Per milestone: the score;
 * per graded scene the student's render, the reference and the diff heatmap side by side as
 * data-URI PNGs, with the metric and the tolerance once and a colour legend of the heatmap; per
 * failed test its full message with its hint. The students' version leaves out what hidden
 * tests said (their own entries in results.json carry it, with their visibility), lists ignored
 * files as one line, and is kept under {@link #STUDENT_BUDGET} characters by downscaling the
 * images. Styles are inline (Gradescope keeps the HTML, not a style sheet) and the layout wraps
 * within any width.
 *
 * <p>One writer for one format: the report's HTML, whose two versions (students', instructors') differ
 * only in what they leave out.
 */
final class HtmlReport {
    /**
     * Size budget of the students' HTML, in characters. Gradescope's autograder specification
     * documents no limit for {@code output}; we keep it at 1 MB so that results.json stays small
     * and the page loads fast.
     */
    static final int STUDENT_BUDGET = 1_000_000;
    /** Widths tried in turn (0 = as rendered) until the students' HTML fits the budget. */
    private static final int[] WIDTHS = {0, 240, 160, 100};

    private static final String PRE = "white-space:pre-wrap;overflow-wrap:anywhere;margin:4px 0;font-size:90%;"
            + "background:#f6f6f6;padding:6px;border-radius:4px";
    private static final String FIG = "flex:1 1 200px;min-width:0;max-width:420px;margin:0";
    private static final String IMG = "display:block;width:100%;height:auto;image-rendering:pixelated;border:1px solid #999";

    private HtmlReport() {
    }

    /** The students' HTML, within the budget (images downscaled as needed). */
    static String forStudents(GradeReport r) {
        String html = "";
        for (int w : WIDTHS) {
            html = build(r, true, w);
            if (html.length() <= STUDENT_BUDGET) {
                return html;
            }
        }
        return build(r, true, -1); // no images at all: still every message
    }

    /** The instructors' page: everything, images as rendered. */
    static String forInstructors(GradeReport r) {
        return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>raylab grade: "
                + fmt(r.score()) + " / " + fmt(r.maxScore()) + "</title></head>\n"
                + "<body style=\"font-family:sans-serif;margin:16px;max-width:1200px\">\n" + build(r, false, 0)
                + "</body></html>\n";
    }

    /** What the students' page says in place of any score that includes hidden tests. */
    static final String HIDDEN_AFTER_DUE = "hidden: results after the due date";

    /** Whether the students may see this item's result now (before the due date). */
    static boolean shownNow(GradeReport.Test t) {
        return "visible".equals(t.visibility());
    }

    private static double visibleScore(List<GradeReport.Test> tests) {
        return GradeReport.round(tests.stream().filter(HtmlReport::shownNow).mapToDouble(GradeReport.Test::score).sum());
    }

    private static double visibleMax(List<GradeReport.Test> tests) {
        return GradeReport.round(tests.stream().filter(HtmlReport::shownNow).mapToDouble(GradeReport.Test::maxScore).sum());
    }

    private static double hiddenMax(List<GradeReport.Test> tests) {
        return GradeReport.round(tests.stream().filter(t -> !shownNow(t)).mapToDouble(GradeReport.Test::maxScore).sum());
    }

    /** The anchor of a graded item on the page. */
    private static String anchor(GradeReport.Milestone m, int index) {
        return "item-" + m.id().replaceAll("[^A-Za-z0-9_-]", "_") + "-" + index;
    }

    /** How many failing items the list at the top names (the rest: "and N more below"). */
    static final int FIX_FIRST = 8;

    /**
     * @param students  the students' version (no hidden messages or scores, ignored files as one line)
     * @param maxWidth  0: images as rendered; > 0: at most this many pixels wide; -1: no images
     */
    private static String build(GradeReport r, boolean students, int maxWidth) {
        StringBuilder b = new StringBuilder();
        b.append("<div style=\"font-family:sans-serif;max-width:100%;overflow-wrap:anywhere\">\n");
        List<GradeReport.Test> all = r.milestones().stream().flatMap(m -> m.tests().stream()).toList();
        if (r.failed()) {
            // Not a score of 0 and never "nothing to fix": no points were decided. The cause (which
            // may name the instructor's paths or hidden tests) is on the instructors' page only.
            b.append("<h1 style=\"font-size:140%;color:#b00020\">The autograder failed: no points were decided</h1>\n");
            if (students) {
                b.append("<p>").append(esc(GradeReport.FAILED_FOR_STUDENTS)).append("</p>\n");
                return b.append("</div>\n").toString();
            }
            b.append("<p>Fix the cause (the course's setup, or the grading machine's load or memory) and grade this"
                    + " submission again. Cause:</p>\n<pre style=\"")
                    .append(PRE).append("\">").append(esc(r.failure())).append("</pre>\n");
            if (r.milestones().isEmpty()) {
                for (String n : r.notes()) {
                    b.append("<pre style=\"").append(PRE).append("\">").append(esc(n)).append("</pre>\n");
                }
                return b.append("</div>\n").toString();
            }
            // The milestones that were graded, below: for the instructors only (no grade was decided).
        }
        if (students) {
            // Before the due date Gradescope shows this page to students at once: only what they
            // can see anyway (visible tests, visible data cases, scenes), never a total with hidden points.
            b.append("<h1 style=\"font-size:140%\">Visible results ").append(fmt(visibleScore(all))).append(" / ")
                    .append(fmt(visibleMax(all))).append("</h1>\n");
            if (hiddenMax(all) > 0) {
                b.append("<p>").append(HIDDEN_AFTER_DUE).append(" (hidden tests and data cases, ")
                        .append(fmt(hiddenMax(all))).append(" points).</p>\n");
            }
        } else {
            b.append("<h1 style=\"font-size:140%\">Score ").append(fmt(r.score())).append(" / ").append(fmt(r.maxScore()))
                    .append("</h1>\n");
        }
        fixFirst(b, r, students);
        b.append("<table style=\"border-collapse:collapse\">");
        for (GradeReport.Milestone m : r.milestones()) {
            b.append("<tr><td style=\"padding:2px 8px\"><b><a href=\"#").append(esc(m.id())).append("\">")
                    .append(esc(m.id())).append("</a></b></td>")
                    .append("<td style=\"padding:2px 8px;text-align:right\">");
            if (students) {
                b.append("visible ").append(fmt(visibleScore(m.tests()))).append(" / ").append(fmt(visibleMax(m.tests())))
                        .append("</td><td style=\"padding:2px 8px;color:#555\">")
                        .append(hiddenMax(m.tests()) > 0 ? HIDDEN_AFTER_DUE : "");
            } else {
                b.append(fmt(m.score())).append(" / ").append(fmt(m.maxScore()));
            }
            b.append("</td><td style=\"padding:2px 8px\">").append(esc(m.title())).append("</td></tr>");
        }
        b.append("</table>\n");
        if (students) {
            if (!r.ignored().isEmpty()) {
                b.append("<p>").append(r.ignored().size()).append(" submitted file").append(r.ignored().size() == 1 ? " was" : "s were")
                        .append(" not graded (only the files your milestones name are; your instructors' report lists them).</p>\n");
            }
        } else {
            b.append("<h2 style=\"font-size:120%\">Submission</h2><pre style=\"").append(PRE).append("\">");
            r.accepted().forEach(a -> b.append("graded: ").append(esc(a)).append('\n'));
            r.ignored().forEach(a -> b.append("ignored: ").append(esc(a)).append('\n'));
            b.append("</pre>\n");
        }
        // The sandbox mode, the grader's setup, the variants' seed and notes on their bounds are for
        // instructors (not in GradeReport.studentNotes, chosen where the grader writes each note):
        // the students' page holds what their code caused.
        for (String n : students ? r.studentNotes() : r.notes()) {
            b.append("<pre style=\"").append(PRE).append("\">").append(esc(n)).append("</pre>\n");
        }
        if (maxWidth > 0) {
            b.append("<p style=\"font-size:85%;color:#555\">(Images shown at most ").append(maxWidth)
                    .append(" pixels wide to keep this page small.)</p>\n");
        }
        for (GradeReport.Milestone m : r.milestones()) {
            milestone(b, m, students, maxWidth);
        }
        b.append("<p style=\"font-size:85%;color:#555\">Graded in ").append(String.format(Locale.ROOT, "%.1f", r.seconds()))
                .append(" s.</p>\n</div>\n");
        return b.toString();
    }

    /**
     * The list at the top: the failing items the reader may see, in handout order (milestone by
     * milestone, tests in the handout's order, then data cases, then scenes), each with the first
     * line of its message and a link to its section.
     */
    private static void fixFirst(StringBuilder b, GradeReport r, boolean students) {
        List<String> items = new java.util.ArrayList<>();
        for (GradeReport.Milestone m : r.milestones()) {
            List<GradeReport.Test> ts = m.tests();
            for (Kind k : List.of(Kind.VISIBLE, Kind.HIDDEN, Kind.CASE, Kind.SCENE)) {
                for (int i = 0; i < ts.size(); i++) {
                    GradeReport.Test t = ts.get(i);
                    if (t.kind() != k || t.passed() || (students && !shownNow(t))) {
                        continue;
                    }
                    String first = GraderSetup.firstLine(t.message()).strip();
                    items.add("<li style=\"margin:2px 0\"><a href=\"#" + anchor(m, i) + "\">" + esc(m.id()) + ": "
                            + esc(t.name()) + "</a>" + (first.isEmpty() ? "" : " — " + esc(clip(first, 160))) + "</li>");
                }
            }
        }
        b.append("<div id=\"fix-first\" style=\"margin:8px 0;padding:6px 10px;border-left:4px solid ")
                .append(items.isEmpty() ? "#16702e" : "#b00020").append(";background:#fafafa\">");
        if (r.milestones().isEmpty()) {
            b.append("<b>Nothing was graded</b> (see below).");
        } else if (items.isEmpty()) {
            b.append("<b>Nothing to fix:</b> every ").append(students ? "visible " : "")
                    .append("test, data case and scene passes.");
        } else {
            b.append("<b>What to fix first</b> (in the handouts' order)<ol style=\"margin:4px 0\">");
            items.stream().limit(FIX_FIRST).forEach(b::append);
            b.append("</ol>");
            if (items.size() > FIX_FIRST) {
                b.append("<div>and ").append(items.size() - FIX_FIRST).append(" more below.</div>");
            }
        }
        b.append("</div>\n");
    }

    private static String clip(String s, int n) {
        return s.length() <= n ? s : s.substring(0, n - 1) + "…";
    }

    private static void milestone(StringBuilder b, GradeReport.Milestone m, boolean students, int maxWidth) {
        b.append("<h2 id=\"").append(esc(m.id())).append("\" style=\"font-size:120%;border-bottom:1px solid #ccc\">")
                .append(esc(m.id())).append(": ").append(esc(m.title())).append(" (");
        if (students) {
            b.append("visible ").append(fmt(visibleScore(m.tests()))).append(" / ").append(fmt(visibleMax(m.tests())));
            if (hiddenMax(m.tests()) > 0) {
                b.append("; ").append(HIDDEN_AFTER_DUE);
            }
        } else {
            b.append(fmt(m.score())).append(" / ").append(fmt(m.maxScore()));
        }
        b.append(")</h2>\n");
        for (String n : m.notes()) {
            b.append("<pre style=\"").append(PRE).append(";color:#b00020\">").append(esc(n)).append("</pre>\n");
        }
        int shownHidden = 0;
        double hiddenMax = 0;
        int passed = 0;
        int total = 0;
        StringBuilder failures = new StringBuilder();
        StringBuilder notes = new StringBuilder();
        StringBuilder failedScenes = new StringBuilder();
        StringBuilder matchingScenes = new StringBuilder();
        int matching = 0;
        for (int i = 0; i < m.tests().size(); i++) {
            GradeReport.Test t = m.tests().get(i);
            if (t.kind() == Kind.SCENE) {
                if (t.passed() && students) {
                    matching++;
                    scene(matchingScenes, t, maxWidth < 0 ? -1 : SMALL, anchor(m, i), false);
                } else {
                    scene(failedScenes, t, maxWidth, anchor(m, i), true);
                }
                continue;
            }
            boolean secret = students && !shownNow(t);
            if (secret) {
                shownHidden++;
                hiddenMax += t.maxScore();
                continue;
            }
            total++;
            if (!t.note().isEmpty()) {
                notes.append("<div style=\"margin:6px 0\"><b style=\"color:#555\">NOTE</b> ").append(esc(t.name()))
                        .append(" <span style=\"color:#555\">(no points taken)</span><pre style=\"").append(PRE)
                        .append("\">").append(esc(t.note())).append("</pre></div>\n");
            }
            if (t.passed()) {
                passed++;
                continue;
            }
            failures.append("<div id=\"").append(anchor(m, i)).append("\" style=\"margin:8px 0\"><b style=\"color:#b00020\">FAIL</b> ")
                    .append(esc(t.name())).append(" <span style=\"color:#555\">(").append(esc(label(t)))
                    .append(", 0 / ").append(fmt(t.maxScore())).append(")</span>")
                    .append("<pre style=\"").append(PRE).append("\">").append(esc(t.message().strip())).append("</pre>");
            if (!t.output().isBlank()) {
                failures.append("<details><summary>what the test printed").append(t.output().contains("more bytes of output dropped")
                        ? " (the output past the cap was dropped)" : "").append("</summary><pre style=\"").append(PRE)
                        .append("\">").append(esc(t.output())).append("</pre></details>");
            }
            failures.append("</div>\n");
        }
        if (total > 0) {
            b.append("<p>").append(passed).append(" of ").append(total).append(students ? " visible" : "")
                    .append(" tests and data cases passed.</p>\n");
        }
        b.append(failures);
        b.append(notes);
        b.append(failedScenes);
        if (matching > 0) {
            b.append("<details style=\"margin:8px 0\"><summary>").append(matching).append(" matching scene")
                    .append(matching == 1 ? "" : "s").append(" (your render beside the reference, small)</summary>")
                    .append(matchingScenes).append("</details>\n");
        }
        if (shownHidden > 0) {
            b.append("<p>Hidden tests and data cases: ").append(shownHidden).append(", ").append(fmt(hiddenMax))
                    .append(" points; ").append(HIDDEN_AFTER_DUE).append(".</p>\n");
        }
    }

    /** Width of the folded images of matching scenes on the students' page. */
    static final int SMALL = 160;

    private static String label(GradeReport.Test t) {
        return switch (t.kind()) {
            case VISIBLE -> "visible test";
            case HIDDEN -> "hidden test";
            case CASE -> "data case";
            case SCENE -> "scene";
        };
    }

    private static void scene(StringBuilder b, GradeReport.Test t, int maxWidth, String id, boolean withDiff) {
        b.append("<div id=\"").append(id).append("\" style=\"margin:12px 0;padding:8px;border:1px solid #ddd;border-radius:4px\">")
                .append("<div><b style=\"color:").append(t.passed() ? "#16702e\">MATCH" : "#b00020\">DIFFERS")
                .append("</b> ").append(esc(t.name())).append(" <span style=\"color:#555\">(").append(fmt(t.score()))
                .append(" / ").append(fmt(t.maxScore())).append(")</span></div>");
        GradeReport.Images im = t.images();
        if (!t.passed() && !t.message().isBlank()) {
            b.append("<pre style=\"").append(PRE).append("\">").append(esc(t.message().strip())).append("</pre>");
        } else if (im != null && !im.metric().isEmpty()) {
            b.append("<div style=\"font-size:90%\">").append(esc(im.metric())).append("</div>");
        }
        if (im != null && maxWidth >= 0) {
            b.append("<div style=\"display:flex;flex-wrap:wrap;gap:8px;margin-top:6px\">");
            String fig = withDiff ? FIG : "flex:0 1 " + maxWidth + "px;min-width:0;margin:0";
            figure(b, "your render", im.student(), maxWidth, fig);
            figure(b, "reference", im.reference(), maxWidth, fig);
            if (withDiff) {
                figure(b, "difference (heatmap)", im.diff(), maxWidth, fig);
            }
            b.append("</div>");
            if (withDiff && im.diff() != null) {
                b.append("<div style=\"font-size:85%;margin-top:4px\">Heatmap: <img alt=\"heatmap legend\" src=\"")
                        .append(LEGEND).append("\" style=\"vertical-align:middle;width:160px;height:10px;border:1px solid #999\">")
                        .append(" black where the pixels are equal, then red, yellow and white at the largest difference."
                                + " A pixel counts as different when a channel differs by more than ")
                        .append(ImageCompare.PIXEL_THRESHOLD).append("/255.</div>");
            }
        }
        if (!t.passed()) {
            b.append(PixelFeedback.html(im)); // issue 40: the worst pixels' ray trees
        }
        b.append("</div>\n");
    }

    private static void figure(StringBuilder b, String caption, byte[] png, int maxWidth, String style) {
        b.append("<figure style=\"").append(style).append("\">");
        byte[] shown = png == null ? null : scaled(png, maxWidth);
        if (shown == null) {
            b.append("<div style=\"height:60px;border:1px dashed #999;text-align:center;padding-top:20px\">(none)</div>");
        } else {
            b.append("<img alt=\"").append(caption).append("\" src=\"data:image/png;base64,")
                    .append(Base64.getEncoder().encodeToString(shown)).append("\" style=\"").append(IMG).append("\">");
        }
        b.append("<figcaption style=\"font-size:85%;text-align:center\">").append(caption).append("</figcaption></figure>");
    }

    /** The PNG at most maxWidth wide (0: unchanged); unreadable bytes are dropped. */
    static byte[] scaled(byte[] png, int maxWidth) {
        if (maxWidth <= 0) {
            return png;
        }
        try {
            BufferedImage img = ImageIO.read(new ByteArrayInputStream(png));
            if (img == null) {
                return null;
            }
            if (img.getWidth() <= maxWidth) {
                return png;
            }
            int h = Math.max(1, (int) Math.round((double) img.getHeight() * maxWidth / img.getWidth()));
            BufferedImage small = new BufferedImage(maxWidth, h, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = small.createGraphics();
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.drawImage(img, 0, 0, maxWidth, h, null);
            g.dispose();
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ImageIO.write(small, "png", out);
            return out.toByteArray();
        } catch (IOException e) {
            return null;
        }
    }

    /** The heatmap's colours from 0 to 1, as a 64×1 PNG data URI. */
    static final String LEGEND = legend();

    private static String legend() {
        BufferedImage img = new BufferedImage(64, 1, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < 64; x++) {
            img.setRGB(x, 0, ImageCompare.heat(x / 63.0));
        }
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ImageIO.write(img, "png", out);
            return "data:image/png;base64," + Base64.getEncoder().encodeToString(out.toByteArray());
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    static String fmt(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        return s.endsWith(".00") ? s.substring(0, s.length() - 3) : s.endsWith("0") && s.contains(".") ? s.substring(0, s.length() - 1) : s;
    }

    static String esc(String s) {
        return Reports.xml(s);
    }

    /** Every data URI of a page, in order (for tests). */
    static List<String> dataUris(String html) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("src=\"(data:image/png;base64,[A-Za-z0-9+/=]+)\"")
                .matcher(html);
        List<String> out = new java.util.ArrayList<>();
        while (m.find()) {
            out.add(m.group(1));
        }
        return out;
    }
}
