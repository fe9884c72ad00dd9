package raylab.inspect;

import java.util.ArrayList;
import java.util.List;

import raylab.light.PointLight;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.scene.Scene;
import raylab.surface.Surface;

/**
 * The scene drawn from above (x across, z down the page) or from the side (z across, y up),
 * as SVG: each surface's outline (a circle for a sphere, its bounding box otherwise), the lights,
 * the eye, and the pixel's eye ray and shadow rays, the student's dashed red, the reference's green.
 */
public final class SceneDrawing {
    static final int SIZE = 320;

    private SceneDrawing() {
    }

    /** {@code top}: seen from above; otherwise from the side. */
    public static String svg(Scene scene, RayTree mine, RayTree ref, boolean top) {
        List<Vec3> pts = new ArrayList<>();
        pts.add(scene.camera.eye);
        for (PointLight l : scene.lights) {
            pts.add(l.position);
        }
        for (RayTree t : List.of(mine, ref)) {
            if (t.hit() && t.point != null && t.point.isFinite()) {
                pts.add(t.point);
            }
        }
        double far = ref.hit() ? ref.t : mine.hit() && Double.isFinite(mine.t) ? mine.t : 1;
        pts.add(mine.eyeP.plus(mine.eyeD.times(far)));
        for (Surface s : scene.surfaces) {
            BoundingBox b = s.boundingBox();
            if (!b.isEmpty() && b.extent().length() < 50 * Math.max(1, scene.camera.eye.length())) {
                pts.add(b.min);
                pts.add(b.max);
            }
        }
        double minU = Double.POSITIVE_INFINITY;
        double maxU = Double.NEGATIVE_INFINITY;
        double minV = Double.POSITIVE_INFINITY;
        double maxV = Double.NEGATIVE_INFINITY;
        for (Vec3 p : pts) {
            if (!p.isFinite()) {
                continue;
            }
            minU = Math.min(minU, u(p, top));
            maxU = Math.max(maxU, u(p, top));
            minV = Math.min(minV, w(p, top));
            maxV = Math.max(maxV, w(p, top));
        }
        double span = Math.max(maxU - minU, maxV - minV) * 1.15 + 1e-9;
        double cu = (minU + maxU) / 2;
        double cv = (minV + maxV) / 2;
        Proj pr = new Proj(cu - span / 2, cv + span / 2, SIZE / span, top);
        StringBuilder b = new StringBuilder();
        b.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(SIZE).append("\" height=\"").append(SIZE)
                .append("\" viewBox=\"0 0 ").append(SIZE).append(' ').append(SIZE)
                .append("\" style=\"background:#fafafa;border:1px solid #ccc\">");
        b.append("<text x=\"4\" y=\"14\" font-size=\"11\">").append(top ? "from above (x →, z ↓)" : "from the side (z →, y ↑)")
                .append("</text>");
        for (Surface s : scene.surfaces) {
            BoundingBox box = s.boundingBox();
            if (box.isEmpty() || !box.min.isFinite() || !box.max.isFinite()) {
                continue;
            }
            double x0 = pr.x(box.min);
            double x1 = pr.x(box.max);
            double y0 = pr.y(box.min);
            double y1 = pr.y(box.max);
            String title = "<title>" + TreeTable.esc(s.name()) + "</title>";
            if (Tracer.kindOf(s).equals("Sphere")) {
                b.append(String.format("<ellipse cx=\"%.1f\" cy=\"%.1f\" rx=\"%.1f\" ry=\"%.1f\" fill=\"#e6e6e6\" stroke=\"#888\">%s</ellipse>",
                        (x0 + x1) / 2, (y0 + y1) / 2, Math.abs(x1 - x0) / 2, Math.abs(y1 - y0) / 2, title));
            } else {
                b.append(String.format("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#eeeeee\" fill-opacity=\"0.6\" stroke=\"#888\">%s</rect>",
                        Math.min(x0, x1), Math.min(y0, y1), Math.max(0.5, Math.abs(x1 - x0)), Math.max(0.5, Math.abs(y1 - y0)), title));
            }
        }
        rays(b, pr, scene, ref, "#1a9641", "", "ref");
        rays(b, pr, scene, mine, "#d7191c", " stroke-dasharray=\"5,3\"", "mine");
        for (PointLight l : scene.lights) {
            b.append(String.format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"#ffd700\" stroke=\"#aa8800\"><title>light %s</title></circle>",
                    pr.x(l.position), pr.y(l.position), TreeTable.esc(l.name)));
        }
        b.append(String.format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"#000\"><title>eye</title></circle>",
                pr.x(scene.camera.eye), pr.y(scene.camera.eye)));
        b.append("<text x=\"4\" y=\"").append(SIZE - 6).append("\" font-size=\"11\" fill=\"#d7191c\">yours (dashed)</text>");
        b.append("<text x=\"110\" y=\"").append(SIZE - 6).append("\" font-size=\"11\" fill=\"#1a9641\">reference</text>");
        return b.append("</svg>").toString();
    }

    private static void rays(StringBuilder b, Proj pr, Scene scene, RayTree t, String colour, String dash, String cls) {
        Vec3 end = t.hit() && t.point != null && t.point.isFinite() ? t.point
                : t.eyeP.plus(t.eyeD.normalize().times(1e3));
        line(b, pr, t.eyeP, end, colour, dash, 2, cls + " eye");
        if (!t.hit() || t.point == null || !t.point.isFinite()) {
            return;
        }
        for (PointLight l : scene.lights) {
            RayTree.Light lt = t.light(l.name);
            if (lt.state == RayTree.State.BEHIND || lt.state == RayTree.State.NOT_LOOKED) {
                continue;
            }
            Vec3 to = lt.state == RayTree.State.BLOCKED && Double.isFinite(lt.blockerT)
                    ? t.point.plus(l.position.minus(t.point).times(lt.blockerT)) : l.position;
            line(b, pr, t.point, to, colour, dash, 1, cls + " shadow");
            if (lt.state == RayTree.State.BLOCKED) {
                b.append(String.format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>", pr.x(to), pr.y(to), colour));
            }
        }
    }

    private static void line(StringBuilder b, Proj pr, Vec3 a, Vec3 c, String colour, String dash, double width, String cls) {
        b.append(String.format("<line class=\"%s\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.0f\"%s/>",
                cls, pr.x(a), pr.y(a), pr.x(c), pr.y(c), colour, width, dash));
    }

    private static double u(Vec3 p, boolean top) {
        return top ? p.x : p.z;
    }

    private static double w(Vec3 p, boolean top) {
        return top ? -p.z : p.y;
    }

    /** World to drawing: u across, w up (flipped for the page). */
    private record Proj(double u0, double w0, double scale, boolean top) {
        double x(Vec3 p) {
            return clamp((u(p, top) - u0) * scale);
        }

        double y(Vec3 p) {
            return clamp((w0 - w(p, top)) * scale);
        }

        private static double clamp(double v) {
            return Double.isFinite(v) ? Math.max(-1e4, Math.min(1e4, v)) : 0;
        }
    }
}
