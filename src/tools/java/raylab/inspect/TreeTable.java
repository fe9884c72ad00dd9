package raylab.inspect;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import raylab.math.Color;
import raylab.render.Image;

/**
 * The two ray trees of a pixel side by side, one row per quantity in the order the ray tracer
 * computes them, each row marked when the two values differ and the row of the first difference
 * marked as such. Used by the {@code inspect} page and by the graded feedback (static HTML).
 */
public final class TreeTable {
    /** One quantity: its label, the student's value, the reference's, whether they differ. */
    public record Row(String quantity, String mine, String reference, boolean differs, boolean first) {
    }

    private TreeTable() {
    }

    public static List<Row> rows(RayTree mine, RayTree ref, Optional<FirstDifference.Difference> first) {
        List<Row> rows = new ArrayList<>();
        String q = first.map(FirstDifference.Difference::quantity).orElse("");
        rows.add(new Row("eye ray r(t) = p + t·d", "p = " + FirstDifference.v(mine.eyeP) + ", d = "
                + FirstDifference.v(mine.eyeD), "the same", false, false));
        boolean sameHit = mine.hit() == ref.hit() && (!mine.hit()
                || mine.surface.equals(ref.surface) && FirstDifference.near(mine.t, ref.t));
        rows.add(row("closest hit", FirstDifference.hit(mine), FirstDifference.hit(ref), !sameHit, q.equals("eye ray")));
        if (mine.hit() || ref.hit()) {
            rows.add(row("normal n (from intersect)", FirstDifference.v(mine.normal), FirstDifference.v(ref.normal),
                    !FirstDifference.near(mine.normal, ref.normal), q.equals("normal")));
            rows.add(row("point x", FirstDifference.v(mine.point), FirstDifference.v(ref.point),
                    !FirstDifference.near(mine.point, ref.point), q.equals("point")));
            rows.add(row("ambient ka·Ia", ambient(mine), ambient(ref), !FirstDifference.near(mine.ambient, ref.ambient)
                    || mine.ambientAdded != ref.ambientAdded && ref.ambient != null && !ref.ambient.isBlack(),
                    q.equals("ambient")));
            for (RayTree.Light r : ref.lights) {
                RayTree.Light m = mine.light(r.name);
                String p = "light '" + r.name + "': ";
                rows.add(row(p + "shadow ray", state(m), state(r), m.state != r.state
                        || m.state == RayTree.State.BLOCKED && !m.blocker.equals(r.blocker),
                        q.equals(p + "shadow ray") || q.equals(p + "in front") || q.equals(p + "direction")));
                rows.add(row(p + "diffuse kd·I·max(0, n·l)", FirstDifference.c(m.diffuse), FirstDifference.c(r.diffuse),
                        !FirstDifference.near(m.diffuse, r.diffuse), q.equals(p + "diffuse")));
                rows.add(row(p + "specular ks·I·max(0, n·h)^p", FirstDifference.c(m.specular),
                        FirstDifference.c(r.specular), !FirstDifference.near(m.specular, r.specular),
                        q.equals(p + "specular")));
            }
        }
        rows.add(row("colour L (8-bit sRGB)", colour(mine.colour), colour(ref.colour),
                !FirstDifference.near(mine.colour, ref.colour), q.equals("colour")));
        return rows;
    }

    private static Row row(String quantity, String mine, String ref, boolean differs, boolean first) {
        return new Row(quantity, mine, ref, differs, first);
    }

    private static String ambient(RayTree t) {
        if (t.ambient == null) {
            return "none";
        }
        return FirstDifference.c(t.ambient) + (t.ambientAdded > 1 ? " (added " + t.ambientAdded + " times)" : "");
    }

    static String state(RayTree.Light l) {
        return switch (l.state) {
            case NOT_LOOKED -> "not looked at";
            case BEHIND -> "behind the surface (n·l ≤ 0): no ray";
            case NO_SHADOW_RAY -> "none needed: nothing can block it";
            case CLEAR -> "clear: reaches the light";
            case BLOCKED -> "blocked by '" + l.blocker + "' at t = " + FirstDifference.num(l.blockerT);
        };
    }

    static String colour(Color c) {
        if (c == null) {
            return "none";
        }
        int rgb = Image.toRgb8(c);
        return FirstDifference.c(c) + " = (" + ((rgb >> 16) & 0xFF) + ", " + ((rgb >> 8) & 0xFF) + ", " + (rgb & 0xFF) + ")";
    }

    /** The rows as a static HTML table (no script, no style sheet: inline styles only). */
    public static String html(List<Row> rows) {
        StringBuilder b = new StringBuilder();
        b.append("<table style=\"border-collapse:collapse;font-size:13px\"><tr><th style=\"text-align:left;padding:2px 6px\">"
                + "quantity</th><th style=\"text-align:left;padding:2px 6px\">yours</th>"
                + "<th style=\"text-align:left;padding:2px 6px\">reference</th></tr>");
        for (Row r : rows) {
            String bg = r.first() ? "#ffd6d6" : r.differs() ? "#fff1d6" : "transparent";
            b.append("<tr class=\"").append(r.first() ? "first" : r.differs() ? "differs" : "same")
                    .append("\" style=\"background:").append(bg).append("\"><td style=\"padding:2px 6px\">")
                    .append(esc(r.quantity())).append(r.first() ? " <b>(first difference)</b>" : "")
                    .append("</td><td style=\"padding:2px 6px;overflow-wrap:anywhere\">").append(esc(r.mine()))
                    .append("</td><td style=\"padding:2px 6px;overflow-wrap:anywhere\">").append(esc(r.reference()))
                    .append("</td></tr>");
        }
        return b.append("</table>").toString();
    }

    /** The rows as JSON objects (quantity, mine, reference, differs, first) added to {@code to}. */
    public static void json(List<Row> rows, com.fasterxml.jackson.databind.node.ArrayNode to) {
        for (Row r : rows) {
            com.fasterxml.jackson.databind.node.ObjectNode n = to.addObject();
            n.put("quantity", r.quantity());
            n.put("mine", r.mine());
            n.put("reference", r.reference());
            n.put("differs", r.differs());
            n.put("first", r.first());
        }
    }

    public static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
