package raylab.grade;

import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.inspect.TreeTable;

/**
 * The graded feedback of a scene that differs (issue 40): its worst pixels, each with the
 * student's ray tree beside the reference's and the first quantity that differs, and the most
 * common first difference, as the trusted render process found them
 * ({@code raylab.inspect.WorstPixels}, computed by {@code TrustedRender} for the graded variant).
 * Static HTML with inline styles only, no script: what Gradescope's and PrairieLearn's sanitisers
 * keep. Only numbers of the two traces and the lecture's words: no reference code, nothing of the
 * hidden tests.
 */
final class PixelFeedback {
    private static final ObjectMapper JSON = new ObjectMapper();

    private PixelFeedback() {
    }

    /** The JSON if it is a readable feedback, else "" (none, or not readable: shown as nothing). */
    static String valid(String json) {
        if (json == null || json.isEmpty()) {
            return "";
        }
        try {
            JsonNode n = JSON.readTree(json);
            return n.path("summary").isTextual() && n.path("pixels").isArray() ? json : "";
        } catch (java.io.IOException | RuntimeException e) {
            return "";
        }
    }

    /** "\nfirst difference: ..." for the scene's message, or "". */
    static String summaryLine(String json) {
        if (json == null || json.isEmpty()) {
            return "";
        }
        try {
            return "\n" + JSON.readTree(json).path("summary").asText();
        } catch (java.io.IOException e) {
            return "";
        }
    }

    /** The section shown under a differing scene's images, or "" when there is no feedback. */
    static String html(GradeReport.Images im) {
        if (im == null || im.pixels() == null || im.pixels().isEmpty()) {
            return "";
        }
        JsonNode n;
        try {
            n = JSON.readTree(im.pixels());
        } catch (java.io.IOException e) {
            return "";
        }
        StringBuilder b = new StringBuilder();
        b.append("<div class=\"raylab-pixels\" style=\"margin-top:8px\"><div style=\"font-weight:bold\">Why pixels differ:"
                + " your ray trees beside the reference's</div><div style=\"margin:4px 0\">")
                .append(TreeTable.esc(n.path("summary").asText())).append("</div>");
        for (JsonNode p : n.path("pixels")) {
            b.append("<details style=\"margin:4px 0\"><summary>pixel (").append(p.path("x").asInt()).append(", ")
                    .append(p.path("y").asInt()).append("), ").append(p.path("imageDifference").asInt())
                    .append("/255 off: ").append(TreeTable.esc(p.path("difference").asText())).append("</summary>");
            List<TreeTable.Row> rows = new ArrayList<>();
            for (JsonNode r : p.path("rows")) {
                rows.add(new TreeTable.Row(r.path("quantity").asText(), r.path("mine").asText(),
                        r.path("reference").asText(), r.path("differs").asBoolean(), r.path("first").asBoolean()));
            }
            b.append("<div style=\"overflow-x:auto\">").append(TreeTable.html(rows)).append("</div></details>");
        }
        b.append("<div style=\"font-size:85%;color:#555\">Traced here with your code and the reference, one ray"
                + " through each pixel's centre; ./raylab inspect shows the same for any pixel of the published"
                + " scenes.</div></div>");
        return b.toString();
    }
}
