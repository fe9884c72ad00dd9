package raylab.oracle;

import java.util.ArrayList;
import java.util.List;

import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.material.NormalColor;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.scene.Scene;
import raylab.surface.Box;
import raylab.surface.Group;
import raylab.surface.Mesh;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * A deliberately plain second renderer of the lecture's model, written independently of the
 * reference: it shares only the loaded scene (read field by field) and the camera's eye rays.
 * Its own arithmetic on double[3]; the plain quadratic for spheres, slabs for boxes, plane plus
 * inside-edge tests for triangles, a linear loop over all primitives, and the lecture's shade():
 * <pre>
 *   result = ka·Ia
 *   for light in lights:
 *       if light in front (n·l &gt; 0) and shadow ray not blocked (0 &lt; t &lt; 1):
 *           result += kd I (n·l) + ks I max(0, n·h)^p
 * </pre>
 * It does not offset shadow rays; instead every decision that rounding could tip (a near miss, a
 * hit at an edge, two surfaces at almost the same t, a blocker within δ of the point or of the
 * light, n·l or n·d almost 0) makes the pixel <em>fragile</em>: the comparison skips fragile
 * pixels and counts them. δ is 1e-9 times the scene's largest coordinate.
 */
final class PlainRenderer {
    /** Relative size of "too close to call". */
    static final double REL = 1e-9;

    private final Scene scene;
    private final List<Prim> prims = new ArrayList<>();
    private final double delta;

    /** One primitive with its material. */
    private static final class Prim {
        final int kind; // 0 sphere, 1 box, 2 triangle
        final double[] a;
        final double[] b;
        final double[] c;
        final double r;
        final Material m;
        final String name;

        /** A sphere around a triangle, for a quick and conservative rejection of far rays. */
        final double[] around;
        final double aroundR;

        Prim(int kind, double[] a, double[] b, double[] c, double r, Material m, String name) {
            this.kind = kind;
            this.a = a;
            this.b = b;
            this.c = c;
            this.r = r;
            this.m = m;
            this.name = name;
            if (kind == 2) {
                around = mul(add(add(a, b), c), 1.0 / 3);
                aroundR = 1.001 * Math.max(len(sub(a, around)), Math.max(len(sub(b, around)), len(sub(c, around))));
            } else {
                around = null;
                aroundR = 0;
            }
        }
    }

    /** A root of a ray with a primitive: t, the outward normal there, and whether rounding could tip it. */
    private record Root(Prim prim, double t, double[] normal, boolean fragile, boolean phantom, int axis) {
    }

    /** A pixel's colour, whether it is fragile, and (on request) the steps that made it. */
    record Pixel(double r, double g, double b, boolean fragile, String trace) {
        @Override
        public String toString() {
            return "rgb(" + r + ", " + g + ", " + b + ")" + (fragile ? " (fragile)" : "");
        }
    }

    PlainRenderer(Scene scene) {
        this.scene = scene;
        double m = 0;
        for (Surface s : scene.surfaces) {
            add(s);
        }
        for (Prim p : prims) {
            m = Math.max(m, maxAbs(p.a));
            if (p.kind == 0) {
                m = Math.max(m, maxAbs(p.a) + p.r);
            } else {
                m = Math.max(m, maxAbs(p.b));
                if (p.c != null) {
                    m = Math.max(m, maxAbs(p.c));
                }
            }
        }
        for (PointLight l : scene.lights) {
            m = Math.max(m, maxAbs(v(l.position)));
        }
        m = Math.max(m, maxAbs(v(scene.camera.eye)));
        this.delta = REL * m;
    }

    private void add(Surface s) {
        if (s instanceof Sphere sp) {
            prims.add(new Prim(0, v(sp.center), null, null, sp.radius, sp.material(), sp.name()));
        } else if (s instanceof Box bx) {
            prims.add(new Prim(1, v(bx.min), v(bx.max), null, 0, bx.material(), bx.name()));
        } else if (s instanceof Triangle t) {
            prims.add(new Prim(2, v(t.a), v(t.b), v(t.c), 0, t.material(), t.name()));
        } else if (s instanceof Mesh mesh) {
            for (Triangle t : mesh.triangles()) {
                add(t);
            }
        } else if (s instanceof Group g) {
            for (Surface m : g.members()) {
                add(m);
            }
        } else {
            throw new IllegalArgumentException("the plain renderer does not know " + s.getClass());
        }
    }

    /** The pixel through whose centre the camera's eye ray passes. */
    Pixel pixel(int ix, int iy, boolean trace) {
        Ray ray = scene.camera.rayThroughPixelCenter(ix, iy);
        return radiance(v(ray.p), v(ray.d), trace ? new StringBuilder() : null);
    }

    private Pixel radiance(double[] p, double[] d, StringBuilder tr) {
        boolean fragile = false;
        double dLen = len(d);
        Root best = null;
        List<Root> all = new ArrayList<>();
        for (Prim pr : prims) {
            roots(pr, p, d, all);
        }
        for (Root h : all) {
            // Eye rays: range [0, +inf).
            if (!h.phantom && h.t >= 0 && (best == null || h.t < best.t)) {
                best = h;
            }
        }
        for (Root h : all) {
            // A root at exactly t = 0 (the eye on the surface in this renderer's own arithmetic) is
            // a hit by the rule (docs/shading.md), not a decision rounding could tip.
            if (Math.abs(h.t) * dLen < delta && !(h.t == 0 && !h.fragile && !h.phantom)) {
                fragile = true; // the eye ray starts on a surface
                note(tr, "fragile: eye ray starts within δ of " + h.prim.name);
            }
            if (best != null && h != best && h.prim != best.prim && Math.abs(h.t - best.t) * dLen < delta) {
                fragile = true; // two surfaces at almost the same t
                note(tr, "fragile: " + h.prim.name + " and " + best.prim.name + " at almost the same t");
            }
            if (h.fragile && h.t >= 0 && (best == null || h.t <= best.t + delta / dLen)) {
                fragile = true; // grazing, at an edge, or a near miss in front of the visible hit
                note(tr, "fragile: grazing/edge/near miss on " + h.prim.name + " at t = " + h.t);
            }
        }
        if (best == null) {
            note(tr, "no hit: background");
            return new Pixel(scene.background.r, scene.background.g, scene.background.b, fragile, text(tr));
        }
        double[] x = add(p, mul(d, best.t));
        double[] nOut = best.normal;
        note(tr, "hit " + best.prim.name + " at t = " + best.t + ", x = " + str(x) + ", outward n = " + str(nOut));
        Material m = best.prim.m;
        if (m instanceof FlatColor f) {
            return new Pixel(f.color.r, f.color.g, f.color.b, fragile, text(tr));
        }
        if (m instanceof NormalColor) {
            return new Pixel((nOut[0] + 1) * 0.5, (nOut[1] + 1) * 0.5, (nOut[2] + 1) * 0.5, fragile, text(tr));
        }
        Lambertian lam = (Lambertian) m;
        double[] dHat = mul(d, 1 / dLen);
        double nd = dot(nOut, dHat);
        if (Math.abs(nd) < REL) {
            fragile = true;
            note(tr, "fragile: n·d almost 0 (" + nd + ")");
        }
        double[] n = nd > 0 ? mul(nOut, -1) : nOut;
        double[] v = mul(dHat, -1);
        double[] result = {0, 0, 0};
        if (!Boolean.FALSE.equals(scene.effects.ambient())) {
            result = new double[] {lam.ka.r * scene.ambient.r, lam.ka.g * scene.ambient.g, lam.ka.b * scene.ambient.b};
            note(tr, "ambient " + str(result));
        }
        for (PointLight light : scene.lights) {
            double[] q = v(light.position);
            double[] toLight = sub(q, x);
            double dist = len(toLight);
            if (dist == 0) {
                note(tr, "light " + light.name + " exactly at x: nothing");
                continue;
            }
            double[] l = mul(toLight, 1 / dist);
            double nl = dot(n, l);
            if (Math.abs(nl) < REL || dist < delta) {
                fragile = true;
                note(tr, "fragile: n·l almost 0 or light within δ (" + nl + ")");
            }
            if (!(nl > 0)) {
                note(tr, "light " + light.name + " behind (n·l = " + nl + ")");
                continue;
            }
            if (!Boolean.FALSE.equals(scene.effects.shadows()) && light.castsShadows) {
                int verdict = blocked(x, q, best.prim, dist, tr);
                if (verdict == FRAGILE) {
                    fragile = true;
                }
                if (verdict == BLOCKED) {
                    note(tr, "light " + light.name + " blocked");
                    continue;
                }
            }
            double[] I = {light.intensity.r, light.intensity.g, light.intensity.b};
            double[] kd = {lam.kd.r, lam.kd.g, lam.kd.b};
            for (int i = 0; i < 3; i++) {
                result[i] += kd[i] * I[i] * nl;
            }
            note(tr, "light " + light.name + ": diffuse kd I (n·l), n·l = " + nl);
            if (m instanceof BlinnPhong bp && !Boolean.FALSE.equals(scene.effects.specular())) {
                double[] h = add(v, l);
                h = mul(h, 1 / len(h));
                double s = Math.pow(Math.max(0, dot(n, h)), bp.p);
                double[] ks = {bp.ks.r, bp.ks.g, bp.ks.b};
                for (int i = 0; i < 3; i++) {
                    result[i] += ks[i] * I[i] * s;
                }
                note(tr, "  specular ks I max(0, n·h)^p = " + s);
            }
        }
        note(tr, "= " + str(result));
        return new Pixel(result[0], result[1], result[2], fragile, text(tr));
    }

    static final int LIT = 0;
    static final int BLOCKED = 1;
    static final int FRAGILE = 2;

    /**
     * Whether something blocks the segment from x to light q: a root with 0 &lt; t &lt; 1 on
     * x + t(q − x). Roots within δ of x on the point's own primitive are the point itself;
     * roots within δ of x on another primitive, or within δ of the light, are too close to call
     * (FRAGILE) — except a box face whose plane holds the light exactly, which is at t = 1 in
     * exact arithmetic and so does not block.
     */
    private int blocked(double[] x, double[] q, Prim own, double dist, StringBuilder tr) {
        double[] d = sub(q, x);
        List<Root> all = new ArrayList<>();
        for (Prim pr : prims) {
            roots(pr, x, d, all);
        }
        boolean fragile = false;
        boolean blocked = false;
        for (Root h : all) {
            double fromX = h.t * dist;
            double fromLight = (1 - h.t) * dist;
            if (Math.abs(fromX) < delta) {
                if (h.prim != own) {
                    fragile = true;
                    note(tr, "  fragile: " + h.prim.name + " touches x");
                }
                continue;
            }
            if (Math.abs(fromLight) < delta) {
                boolean exact = h.prim.kind == 1 && h.axis >= 0 && !h.phantom
                        && (q[h.axis] == h.prim.a[h.axis] || q[h.axis] == h.prim.b[h.axis]);
                if (!exact) {
                    fragile = true;
                    note(tr, "  fragile: " + h.prim.name + " within δ of the light");
                }
                continue;
            }
            if (h.t > 0 && h.t < 1) {
                if (h.fragile) {
                    fragile = true;
                    note(tr, "  fragile: grazing/edge/near miss of the shadow ray on " + h.prim.name);
                }
                if (!h.phantom) {
                    blocked = true;
                    note(tr, "  shadow ray blocked by " + h.prim.name + " at t = " + h.t);
                }
            }
        }
        if (fragile) {
            return FRAGILE;
        }
        return blocked ? BLOCKED : LIT;
    }

    /** Every root of p + t·d with the primitive, whatever its t; near misses as phantom roots. */
    private void roots(Prim pr, double[] p, double[] d, List<Root> out) {
        switch (pr.kind) {
            case 0 -> sphereRoots(pr, p, d, out);
            case 1 -> boxRoots(pr, p, d, out);
            default -> triangleRoots(pr, p, d, out);
        }
    }

    /** The lecture's quadratic: (d·d) t² + 2 d·(p − c) t + (p − c)·(p − c) − r² = 0. */
    private static void sphereRoots(Prim s, double[] p, double[] d, List<Root> out) {
        double[] f = sub(p, s.a);
        double a = dot(d, d);
        double b = dot(d, f);
        double c = dot(f, f) - s.r * s.r;
        double disc = b * b - a * c;
        boolean grazing = Math.abs(disc) < 1e-7 * a * s.r * s.r;
        if (disc < 0) {
            if (grazing) {
                out.add(new Root(s, -b / a, null, true, true, -1));
            }
            return;
        }
        double sq = Math.sqrt(disc);
        for (double t : new double[] {(-b - sq) / a, (-b + sq) / a}) {
            double[] x = add(p, mul(d, t));
            double[] n = mul(sub(x, s.a), 1 / s.r);
            out.add(new Root(s, t, n, grazing, false, -1));
        }
    }

    /** Slabs: the ray is inside the box from the last slab entry to the first slab exit. */
    private static void boxRoots(Prim bx, double[] p, double[] d, List<Root> out) {
        double enter = Double.NEGATIVE_INFINITY;
        double exit = Double.POSITIVE_INFINITY;
        double enter2 = Double.NEGATIVE_INFINITY; // second-largest entry: an edge when it ties
        double exit2 = Double.POSITIVE_INFINITY;
        int enterAxis = -1;
        int exitAxis = -1;
        boolean fragile = false;
        for (int i = 0; i < 3; i++) {
            double lo = bx.a[i];
            double hi = bx.b[i];
            if (d[i] == 0) {
                if (p[i] < lo || p[i] > hi) {
                    return;
                }
                if (p[i] == lo || p[i] == hi) {
                    fragile = true; // travelling exactly in the plane of a face
                }
                continue;
            }
            double t0 = (lo - p[i]) / d[i];
            double t1 = (hi - p[i]) / d[i];
            double in = Math.min(t0, t1);
            double outT = Math.max(t0, t1);
            if (in > enter) {
                enter2 = enter;
                enter = in;
                enterAxis = i;
            } else if (in > enter2) {
                enter2 = in;
            }
            if (outT < exit) {
                exit2 = exit;
                exit = outT;
                exitAxis = i;
            } else if (outT < exit2) {
                exit2 = outT;
            }
        }
        double scale = Math.max(Math.abs(enter), Math.abs(exit));
        double tol = 1e-9 * (Double.isFinite(scale) ? scale : 0) + 1e-300;
        if (enter > exit) {
            if (enter - exit < tol) {
                out.add(new Root(bx, enter, null, true, true, -1)); // near miss past an edge
            }
            return;
        }
        boolean edge = exit - enter < tol;
        if (enterAxis >= 0) {
            double[] n = {0, 0, 0};
            n[enterAxis] = -Math.signum(d[enterAxis]);
            boolean atEdge = fragile || edge || (Double.isFinite(enter2) && enter - enter2 < tol);
            out.add(new Root(bx, enter, n, atEdge, false, enterAxis));
        }
        if (exitAxis >= 0) {
            double[] n = {0, 0, 0};
            n[exitAxis] = Math.signum(d[exitAxis]);
            boolean atEdge = fragile || edge || (Double.isFinite(exit2) && exit2 - exit < tol);
            out.add(new Root(bx, exit, n, atEdge, false, exitAxis));
        }
    }

    /** The plane, then the point on the inner side of all three edges. */
    private static void triangleRoots(Prim tri, double[] p, double[] d, List<Root> out) {
        // Skip lines that pass the triangle's surrounding sphere by a wide margin (no root at all).
        double fx = tri.around[0] - p[0];
        double fy = tri.around[1] - p[1];
        double fz = tri.around[2] - p[2];
        double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        double s = (fx * d[0] + fy * d[1] + fz * d[2]) / dd;
        double gx = fx - s * d[0];
        double gy = fy - s * d[1];
        double gz = fz - s * d[2];
        if (gx * gx + gy * gy + gz * gz > 1.01 * tri.aroundR * tri.aroundR) {
            return;
        }
        double[] ab = sub(tri.b, tri.a);
        double[] ac = sub(tri.c, tri.a);
        double[] n = cross(ab, ac);
        double nn = dot(n, n);
        if (nn == 0) {
            return;
        }
        double denom = dot(d, n);
        boolean grazing = Math.abs(denom) < 1e-9 * len(d) * Math.sqrt(nn);
        if (denom == 0) {
            return;
        }
        double t = dot(sub(tri.a, p), n) / denom;
        double[] x = add(p, mul(d, t));
        double e0 = dot(cross(sub(tri.b, tri.a), sub(x, tri.a)), n);
        double e1 = dot(cross(sub(tri.c, tri.b), sub(x, tri.b)), n);
        double e2 = dot(cross(sub(tri.a, tri.c), sub(x, tri.c)), n);
        double tol = 1e-7 * nn;
        boolean nearEdge = Math.abs(e0) < tol || Math.abs(e1) < tol || Math.abs(e2) < tol;
        boolean inside = e0 >= 0 && e1 >= 0 && e2 >= 0;
        double[] unit = mul(n, 1 / Math.sqrt(nn));
        if (inside) {
            out.add(new Root(tri, t, unit, grazing || nearEdge, false, -1));
        } else if (nearEdge && e0 > -tol && e1 > -tol && e2 > -tol) {
            out.add(new Root(tri, t, unit, true, true, -1));
        }
    }

    // ---- plain vector arithmetic on double[3]

    static double[] v(Vec3 a) {
        return new double[] {a.x, a.y, a.z};
    }

    static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double[] mul(double[] a, double s) {
        return new double[] {a[0] * s, a[1] * s, a[2] * s};
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    static double len(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    static double maxAbs(double[] a) {
        return Math.max(Math.abs(a[0]), Math.max(Math.abs(a[1]), Math.abs(a[2])));
    }

    static String str(double[] a) {
        return a == null ? "-" : "(" + a[0] + ", " + a[1] + ", " + a[2] + ")";
    }

    private static void note(StringBuilder tr, String s) {
        if (tr != null) {
            tr.append("\n      ").append(s);
        }
    }

    private static String text(StringBuilder tr) {
        return tr == null ? "" : tr.toString();
    }
}
