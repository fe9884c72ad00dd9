package raylab.inspect;

import java.util.Optional;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.scene.Scene;
import raylab.surface.Surface;

/**
 * Compares the student's ray tree of a pixel with the reference's, quantity by quantity in the
 * order the ray tracer computes them (the eye ray's closest hit: surface, t, normal, point; the
 * ambient term; each light: in front or behind, its shadow ray, its diffuse and specular terms;
 * the colour), and names the first that differs in the lecture's words, with the method that
 * computed it. Numbers agree within {@link #REL} relative (the shipped reference traces are
 * rounded to at most 9.8e-4 relative, {@code TraceFile}; a correct intersect written another way
 * differs by far less than this). A difference that changes a pixel by the grader's 2/255 is at
 * least 1.8 % of the linear colour (the sRGB curve's steepest relative slope, at 1), six times REL.
 */
public final class FirstDifference {
    /** Relative tolerance of t, normals, points and colours. */
    static final double REL = 3e-3;

    /**
     * The first difference.
     *
     * @param quantity which quantity: "eye ray", "normal", "point", "ambient", "light 'key' shadow ray", ...
     * @param line     the one-line explanation ("eye ray: your closest hit is ...: your Sphere.intersect ...")
     * @param method   the student method it points to (Sphere.intersect, Shadows.isShadowed, ...)
     */
    public record Difference(String quantity, String line, String method) {
    }

    private FirstDifference() {
    }

    /**
     * The first quantity in which {@code mine} differs from {@code ref}; empty when they agree.
     * {@code scene} is the student's own scene (its surfaces run the student's intersect): a
     * difference of the closest hit is narrowed down by asking single surfaces; null: not narrowed.
     */
    public static Optional<Difference> of(RayTree mine, RayTree ref, Scene scene) {
        Optional<Difference> d = eyeRay(mine, ref, scene);
        if (d.isPresent() || !ref.hit() || !mine.hit()) {
            return d.isPresent() ? d : colourOnly(mine, ref);
        }
        String where = "'" + ref.surface + "'";
        if (!near(mine.normal, ref.normal)) {
            String m = mine.kind + ".intersect";
            String why;
            if (mine.normal != null && near(mine.normal.negate(), ref.normal)) {
                why = "it points into the surface: the normal must point out of the surface, whichever side the ray"
                        + " comes from";
            } else if (mine.normal != null && Math.abs(mine.normal.length() - 1) > REL) {
                why = "it is not a unit vector (length " + num(mine.normal.length()) + "): normalise it";
            } else {
                why = "it is not the surface's normal at the hit point";
            }
            return Optional.of(new Difference("normal", "normal at " + where + ": yours is n = " + v(mine.normal)
                    + ", the reference's n = " + v(ref.normal) + ": your " + m + " records a normal where " + why, m));
        }
        if (!near(mine.point, ref.point)) {
            String m = mine.kind + ".intersect";
            return Optional.of(new Difference("point", "hit point on " + where + ": yours is x = " + v(mine.point)
                    + ", the reference's x = p + t·d = " + v(ref.point) + ": your " + m
                    + " records a point that is not r(t) = p + t·d", m));
        }
        if (!ref.lit) {
            return colourOnly(mine, ref);
        }
        if (!near(mine.ambient, ref.ambient)) {
            String why;
            if (mine.ambient == null || mine.ambientAdded == 0) {
                why = "your Shading.shade leaves out the ambient term: start with result = ka·Ia";
            } else if (mine.ambientAdded > 1) {
                why = "your Shading.shade adds the ambient term " + mine.ambientAdded
                        + " times: add ka·Ia once, before the loop over the lights";
            } else {
                why = "your Shading.shade's ambient term is not ka·Ia";
            }
            return Optional.of(new Difference("ambient", "ambient term ka·Ia: yours is " + c(mine.ambient)
                    + ", the reference's " + c(ref.ambient) + ": " + why, "Shading.shade"));
        }
        for (RayTree.Light r : ref.lights) {
            RayTree.Light l = mine.light(r.name);
            Optional<Difference> ld = light(l, r, mine);
            if (ld.isPresent()) {
                return ld;
            }
        }
        return colourOnly(mine, ref);
    }

    private static Optional<Difference> eyeRay(RayTree mine, RayTree ref, Scene scene) {
        if (!mine.hit() && !ref.hit()) {
            return Optional.empty();
        }
        if (mine.hit() && ref.hit() && mine.surface.equals(ref.surface) && near(mine.t, ref.t)) {
            return Optional.empty();
        }
        String head = "eye ray: your closest hit is " + hit(mine) + ", the reference's " + hit(ref) + ": ";
        if (!mine.hit()) {
            String m = kindOf(scene, ref.surface, ref.kind) + ".intersect";
            return Optional.of(new Difference("eye ray", head + "your " + m + " misses '" + ref.surface
                    + "' where the ray meets it", m));
        }
        if (!ref.hit()) {
            return Optional.of(new Difference("eye ray", head + "your " + mine.kind + ".intersect reports a hit where"
                    + " the ray passes '" + mine.surface + "' by", mine.kind + ".intersect"));
        }
        if (mine.surface.equals(ref.surface)) {
            String m = mine.kind + ".intersect";
            String why;
            if (mine.t > ref.t) {
                why = switch (mine.kind) {
                    case "Sphere" -> "your Sphere.intersect returns the farther root: the closest hit is the smaller"
                            + " root t in [tMin, tMax]";
                    case "Box" -> "your Box.intersect returns the exit t: the closest hit is where the ray enters"
                            + " the box, t_enter = max of the slabs' near t";
                    default -> "your " + m + " returns a t beyond the closest hit";
                };
            } else {
                why = "your " + m + " returns a t before the surface";
            }
            return Optional.of(new Difference("eye ray", head + why, m));
        }
        // Two different surfaces: ask each of the student's surfaces alone.
        if (mine.t > ref.t) {
            double alone = alone(scene, ref.surface, mine);
            if (Double.isFinite(alone) && near(alone, ref.t)) {
                String m = mine.kind + ".intersect";
                return Optional.of(new Difference("eye ray", head + "your " + m + " for '" + mine.surface
                        + "' replaced the closer hit at t = " + num(ref.t) + ": it must record a hit only when its t"
                        + " is closer than outRecord.t (within the ray's [tMin, tMax])", m));
            }
            String m = kindOf(scene, ref.surface, ref.kind) + ".intersect";
            return Optional.of(new Difference("eye ray", head + "your " + m + " misses '" + ref.surface
                    + "' where the ray meets it", m));
        }
        String m = mine.kind + ".intersect";
        return Optional.of(new Difference("eye ray", head + "your " + m + " reports a hit on '" + mine.surface
                + "' at t = " + num(mine.t) + " where the reference finds none before t = " + num(ref.t), m));
    }

    private static Optional<Difference> light(RayTree.Light l, RayTree.Light r, RayTree mine) {
        String name = "light '" + r.name + "': ";
        boolean refFront = r.state != RayTree.State.BEHIND && r.state != RayTree.State.NOT_LOOKED;
        boolean myFront = l.state != RayTree.State.BEHIND && l.state != RayTree.State.NOT_LOOKED;
        if (l.state == RayTree.State.NOT_LOOKED && r.state != RayTree.State.NOT_LOOKED) {
            return Optional.of(new Difference(name + "direction", name + "your Shading.shade never computes the"
                    + " direction l to this light: loop over every light", "Shading.shade"));
        }
        if (refFront != myFront) {
            return Optional.of(new Difference(name + "in front", name + (myFront
                    ? "your Shading.shade lights the point although the light is behind the surface (n·l ≤ 0):"
                            + " skip such a light"
                    : "your Shading.shade skips it although it is in front of the surface (n·l > 0)"), "Shading.shade"));
        }
        if (!refFront) {
            return Optional.empty();
        }
        boolean myBlocked = l.state == RayTree.State.BLOCKED;
        boolean refBlocked = r.state == RayTree.State.BLOCKED;
        if (myBlocked && !refBlocked) {
            String m = "Shadows.isShadowed";
            String why = l.blocker != null && l.blocker.equals(mine.surface) && l.blockerT < 1e-4
                    ? ": shadow acne, the shadow ray meets the surface it starts on; start it a small distance off"
                            + " the surface (or raise tMin above 0)"
                    : l.blockerT >= Math.nextDown(1.0) - 1e-9
                            ? ": a blocker must lie strictly between the point and the light, 0 < t < 1"
                            : ": the reference's shadow ray reaches the light";
            return Optional.of(new Difference(name + "shadow ray", name + "your shadow ray is blocked by '" + l.blocker
                    + "' at t = " + num(l.blockerT) + ", the reference's is not" + why, m));
        }
        if (!myBlocked && refBlocked) {
            return Optional.of(new Difference(name + "shadow ray", name + "your shadow ray reaches the light, the"
                    + " reference's is blocked by '" + r.blocker + "' at t = " + num(r.blockerT) + " (t = 1 is the light):"
                    + " your Shadows.isShadowed misses a blocker between the point and the light (an offset or"
                    + " range that skips 0 < t < 1?)", "Shadows.isShadowed"));
        }
        if (myBlocked) {
            return Optional.empty();
        }
        if (!near(l.diffuse, r.diffuse)) {
            return Optional.of(new Difference(name + "diffuse", name + "diffuse term kd·I·max(0, n·l): yours is "
                    + c(l.diffuse) + ", the reference's " + c(r.diffuse) + ": your " + (l.diffuse == null
                            ? "Shading.shade does not add it" : "Lambertian.diffuse"),
                    l.diffuse == null ? "Shading.shade" : "Lambertian.diffuse"));
        }
        if (!near(l.specular, r.specular)) {
            String why = specularWhy(l.specular, r.specular);
            return Optional.of(new Difference(name + "specular", name + "specular term ks·I·max(0, n·h)^p: yours is "
                    + c(l.specular) + ", the reference's " + c(r.specular) + ": " + why,
                    l.specular == null ? "Shading.shade" : "BlinnPhong.specular"));
        }
        return Optional.empty();
    }

    /** What a wrong specular term suggests. */
    private static String specularWhy(Color mine, Color ref) {
        if (mine == null) {
            return "your Shading.shade does not add it";
        }
        double a = mine.r + mine.g + mine.b;
        double b = ref == null ? 0 : ref.r + ref.g + ref.b;
        if (a > b) {
            return "your BlinnPhong.specular is too bright here: is h = (l + v)/‖l + v‖ a unit vector, and is n·h"
                    + " (not n·l, not r·v) raised to p?";
        }
        return "your BlinnPhong.specular is too dark here: n·h with the unit half vector h = (l + v)/‖l + v‖,"
                + " clamped at 0, then raised to p";
    }

    private static Optional<Difference> colourOnly(RayTree mine, RayTree ref) {
        if (near(mine.colour, ref.colour)) {
            return Optional.empty();
        }
        String m = ref.lit ? "Shading.shade" : mine.kind + ".intersect";
        return Optional.of(new Difference("colour", "colour L: yours is " + c(mine.colour) + ", the reference's "
                + c(ref.colour) + (ref.lit ? ", with the same terms: your Shading.shade sums them differently"
                        + " (L = ka·Ia + Σ diffuse + specular over the lights in front and visible)" : ""), m));
    }

    /** The t at which the student's surface of that name alone meets the eye ray (NaN: none, or not found). */
    private static double alone(Scene scene, String name, RayTree mine) {
        if (scene == null) {
            return Double.NaN;
        }
        for (Surface s : scene.surfaces) {
            if (name.equals(s.name())) {
                IntersectionRecord rec = new IntersectionRecord();
                Ray ray = new Ray(mine.eyeP, mine.eyeD, 0, Double.POSITIVE_INFINITY);
                try {
                    return s.intersect(rec, ray) ? rec.t : Double.NaN;
                } catch (RuntimeException e) {
                    return Double.NaN;
                }
            }
        }
        return Double.NaN;
    }

    private static String kindOf(Scene scene, String name, String fallback) {
        if (scene != null) {
            for (Surface s : scene.surfaces) {
                if (name.equals(s.name())) {
                    return Tracer.kindOf(s);
                }
            }
        }
        return fallback == null || fallback.equals("?") ? "Surface" : fallback;
    }

    static String hit(RayTree t) {
        return t.hit() ? "'" + t.surface + "' at t = " + num(t.t) : "nothing (background)";
    }

    static boolean near(double a, double b) {
        return a == b || Math.abs(a - b) <= REL * Math.max(1e-3, Math.max(Math.abs(a), Math.abs(b)));
    }

    static boolean near(Vec3 a, Vec3 b) {
        if (a == null || b == null) {
            return a == b;
        }
        double scale = Math.max(1, Math.max(a.length(), b.length()));
        return Math.abs(a.x - b.x) <= REL * scale && Math.abs(a.y - b.y) <= REL * scale
                && Math.abs(a.z - b.z) <= REL * scale;
    }

    /** Colours agree within REL absolute or relative; a missing term counts as black. */
    static boolean near(Color a, Color b) {
        Color x = a == null ? Color.BLACK : a;
        Color y = b == null ? Color.BLACK : b;
        return close(x.r, y.r) && close(x.g, y.g) && close(x.b, y.b);
    }

    private static boolean close(double a, double b) {
        return a == b || Math.abs(a - b) <= REL * Math.max(1, Math.max(Math.abs(a), Math.abs(b)));
    }

    static String num(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        String s = Math.abs(v) != 0 && (Math.abs(v) < 1e-3 || Math.abs(v) >= 1e6) ? String.format("%.3g", v)
                : String.format("%.4g", v);
        return s.contains("e") ? s.replaceFirst("\\.?0+e", "e").replaceFirst("e([+-])0*(\\d)", "e$1$2").replace("e+", "e")
                : s.replaceFirst("(\\.\\d*?)0+$", "$1").replaceFirst("\\.$", "");
    }

    static String v(Vec3 a) {
        return a == null ? "none" : "(" + num(a.x) + ", " + num(a.y) + ", " + num(a.z) + ")";
    }

    static String c(Color a) {
        return a == null ? "none" : "rgb(" + num(a.r) + ", " + num(a.g) + ", " + num(a.b) + ")";
    }
}
