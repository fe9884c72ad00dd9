package raylab.testing;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiFunction;

import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Assertions for the milestone tests, with failure messages that show the ray, the surface,
 * what was expected, what came back, and a HINT about the likely mistake.
 *
 * <p>Tolerances: t within 1e-9 relative, points within 1e-9 (times the size of the coordinates),
 * unit normals within 1e-9 per component, colours within 1e-9 relative per channel.
 */
public final class Check {
    public static final double TOL = 1e-9;

    private Check() {
    }

    // ---------------------------------------------------------------- notes

    /**
     * Reports a zero-point note: the result was right, but it cost more than the render plan
     * needs. The grader and {@code check} show it beside the test; it never changes a score.
     */
    public static void note(String text) {
        System.out.println(raylab.course.Notes.PREFIX + text);
    }

    /**
     * The note for shadow rays the plan could skip: {@code extra} questions
     * {@code at.visible(light)} for lights with n·l ≤ 0. Nothing when {@code extra} is 0.
     */
    public static void skippableShadowRays(int extra) {
        if (extra > 0) {
            note("your loop traced " + extra + " shadow ray" + (extra == 1 ? "" : "s") + " the plan could skip:"
                    + " at.visible(light) was asked for a light with n·l <= 0 (behind the surface or on its horizon),"
                    + " which adds nothing whatever the answer; test n·l > 0 first and you save the ray (no points"
                    + " are taken for this)");
        }
    }

    // ---------------------------------------------------------------- intersections

    private static final ExecutorService WORKERS = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "raylab-render");
        t.setDaemon(true);
        return t;
    });

    /**
     * {@code s.intersect(rec, ray)}, called the way the renderer calls it: on a worker thread
     * ({@code raylab-render}) whose call stack holds no test. Code that behaves differently under
     * a test is graded on what it renders. What {@code intersect} throws is rethrown unchanged; a
     * breakpoint inside it still stops there.
     */
    public static boolean intersect(Surface s, IntersectionRecord rec, Ray ray) {
        // A bound method reference: its adapter is a hidden class, so no frame of a test class
        // sits on the worker's stack.
        BiFunction<IntersectionRecord, Ray, Boolean> call = s::intersect;
        CompletableFuture<Boolean> result = CompletableFuture.completedFuture(rec)
                .thenCombineAsync(CompletableFuture.completedFuture(ray), call, WORKERS);
        try {
            return result.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for intersect", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException re) {
                throw re;
            }
            if (cause instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(cause);
        }
    }

    /** Asserts that {@code s} hits {@code ray} at t with this point and unit outward normal. */
    public static IntersectionRecord hit(Surface s, Ray ray, double t, Vec3 point, Vec3 normal) {
        return hit(new IntersectionRecord(), s, ray, t, point, normal, null);
    }

    /** The same, with a hint to show if it fails. */
    public static IntersectionRecord hit(Surface s, Ray ray, double t, Vec3 point, Vec3 normal,
            String hint) {
        return hit(new IntersectionRecord(), s, ray, t, point, normal, hint);
    }

    /** The same, starting from a given record (for example one that holds a farther hit). */
    public static IntersectionRecord hit(IntersectionRecord rec, Surface s, Ray ray, double t,
            Vec3 point, Vec3 normal, String hint) {
        double recordT = rec.t;
        boolean returned = intersect(s, rec, ray);
        String expected = "hit at t=" + t + ", point " + point + ", normal " + normal;
        boolean wrote = rec.t != recordT;
        if (!returned || !wrote) {
            boolean neither = !returned && !wrote;
            String why = neither ? "no hit"
                    : returned ? "returned true but did not write the record"
                    : "wrote the record but returned false";
            String auto = neither ? insideHint(s, ray)
                    : "return true exactly when you write the record";
            fail(message(why, s, ray, expected, rec, returned, auto, hint));
        }
        String problem = null;
        String auto = null;
        double dLength = ray.d.length();
        if (!(Math.abs(rec.t - t) <= TOL * Math.abs(t))) {
            problem = "wrong t";
            if (Math.abs(rec.t - t * dLength) <= TOL * Math.abs(t * dLength)) {
                auto = "t is the distance along d/‖d‖ here: you may be assuming d is a unit vector"
                        + " (‖d‖ = " + dLength + ")";
            } else if (!ray.inRange(rec.t)) {
                String inside = insideHint(s, ray);
                auto = "t = " + rec.t + " is outside the ray's range [tMin, tMax]"
                        + (inside == null ? "" : "; " + inside);
            }
        } else if (rec.point == null || !close(rec.point, point, TOL * scale(ray.p, point))) {
            problem = "wrong point";
            auto = "the point is r(t) = p + t·d";
        } else if (rec.normal == null || !close(rec.normal, normal, TOL)) {
            problem = "wrong normal";
            if (rec.normal != null && close(rec.normal, normal.negate(), TOL)) {
                auto = "the normal must point out of the surface, whichever side the ray"
                        + " comes from";
            } else if (rec.normal != null && close(rec.normal.normalize(), normal, TOL)) {
                auto = "normalize the normal: it must have length 1";
            }
        } else if (rec.surface != s || rec.material != s.material()) {
            problem = "the record does not name this surface and its material";
            auto = "outRecord.set(t, point, normal, this) fills in every field";
        }
        if (problem != null) {
            fail(message(problem, s, ray, expected, rec, returned, auto, hint));
        }
        return rec;
    }

    /** Asserts that {@code s} does not hit {@code ray}: returns false, record left empty. */
    public static void miss(Surface s, Ray ray, String hint) {
        untouched(new IntersectionRecord(), s, ray, hint);
    }

    /**
     * Asserts that intersecting returns false and leaves every field of the record as it was
     * (t, point, normal, surface, material).
     */
    public static void untouched(IntersectionRecord rec, Surface s, Ray ray, String hint) {
        IntersectionRecord before = new IntersectionRecord();
        before.copyFrom(rec);
        boolean returned = intersect(s, rec, ray);
        boolean same = Double.compare(rec.t, before.t) == 0 && rec.point == before.point
                && rec.normal == before.normal && rec.surface == before.surface
                && rec.material == before.material;
        if (returned || !same) {
            String auto;
            if (!returned) {
                auto = "leave the record untouched when you return false";
            } else if (same) {
                auto = "return true only when you write the record";
            } else if (before.hasHit() && rec.t >= before.t) {
                auto = "only write the record when the new t < outRecord.t (" + before.t + ")";
            } else if (!ray.inRange(rec.t)) {
                auto = "t = " + rec.t + " is outside [tMin, tMax]"
                        + (rec.t < ray.tMin ? ": a hit behind the ray's start does not count" : "");
            } else {
                auto = null;
            }
            fail(message(returned ? "returned true" : "changed the record", s, ray,
                    "no hit (return false, record untouched: " + before + ")", rec, returned,
                    auto, hint));
        }
    }

    /**
     * A record that already holds a hit at t on a sentinel surface, as a group's record does
     * after a closer surface was found.
     */
    public static IntersectionRecord recordWithHitAt(double t) {
        IntersectionRecord rec = new IntersectionRecord();
        Surface sentinel = new Sphere(new Vec3(99, 99, 99), 1,
                new Lambertian(Color.WHITE, Color.BLACK, "sentinel material"), "sentinel");
        rec.set(t, new Vec3(7, 7, 7), new Vec3(0, 1, 0), sentinel);
        return rec;
    }

    private static String insideHint(Surface s, Ray ray) {
        Vec3 start = ray.evaluate(ray.tMin);
        boolean inside = s instanceof Sphere sp
                ? start.minus(sp.center).length() < sp.radius
                : s instanceof Box b && b.min.x < start.x && start.x < b.max.x
                        && b.min.y < start.y && start.y < b.max.y
                        && b.min.z < start.z && start.z < b.max.z;
        return inside ? "the ray starts inside (at r(tMin)): where it enters is behind its start,"
                + " so the hit is where it leaves (the farther root, t_exit)" : null;
    }

    private static String message(String problem, Surface s, Ray ray, String expected,
            IntersectionRecord rec, boolean returned, String... hints) {
        StringBuilder m = new StringBuilder(problem)
                .append("\n  surface:  ").append(describe(s))
                .append("\n  ray:      ").append(describe(ray))
                .append("\n  expected: ").append(expected)
                .append("\n  got:      returned ").append(returned)
                .append(", record: ").append(rec);
        for (String h : hints) {
            if (h != null) {
                m.append("\nHINT: ").append(h);
            }
        }
        return m.append('\n').toString();
    }

    /** A ray in the lecture's terms, for messages: r(t) = p + t·d with its range. */
    public static String describe(Ray ray) {
        return "p=" + ray.p + " d=" + ray.d + " t in [" + ray.tMin + ", " + ray.tMax + "]";
    }

    /** The surface's name and shape, for messages. */
    public static String describe(Surface s) {
        if (s instanceof Sphere sp) {
            return "sphere '" + s.name() + "' centre " + sp.center + " radius " + sp.radius;
        } else if (s instanceof Box b) {
            return "box '" + s.name() + "' min " + b.min + " max " + b.max;
        } else if (s instanceof Triangle tr) {
            return "triangle '" + s.name() + "' a=" + tr.a + " b=" + tr.b + " c=" + tr.c;
        }
        return "'" + s.name() + "'";
    }

    // ---------------------------------------------------------------- shadows

    /** Asserts that the light is blocked at x, and that scratch names the expected blocker. */
    public static void shadowed(Surface scene, Vec3 x, Vec3 n, PointLight light, Surface blocker,
            String hint) {
        IntersectionRecord scratch = new IntersectionRecord();
        boolean result = raylab.shading.Shadows.isShadowed(scene, x, n, light, scratch);
        if (!result || scratch.surface != blocker) {
            fail(shadowMessage(result ? "the scratch record names the wrong blocker"
                    : "not shadowed", x, n, light, "shadowed by " + describe(blocker), result,
                    scratch, hint));
        }
    }

    /** Asserts that nothing blocks the light at x. */
    public static void lit(Surface scene, Vec3 x, Vec3 n, PointLight light, String hint) {
        IntersectionRecord scratch = new IntersectionRecord();
        if (raylab.shading.Shadows.isShadowed(scene, x, n, light, scratch)) {
            fail(shadowMessage("shadowed", x, n, light, "lit (nothing blocks the light)", true,
                    scratch, hint));
        }
    }

    private static String shadowMessage(String problem, Vec3 x, Vec3 n, PointLight light,
            String expected, boolean result, IntersectionRecord scratch, String hint) {
        return problem
                + "\n  point x=" + x + " normal n=" + n + " light at " + light.position
                + "\n  expected: " + expected
                + "\n  got:      isShadowed returned " + result + ", scratch record: "
                + (scratch.hasHit() ? "t=" + scratch.t + " on " + describe(scratch.surface)
                        : "no hit")
                + (scratch.hasHit() && scratch.t < 1e-4 ? "\nHINT: the shadow ray hit something at"
                        + " t ≈ 0, where it starts: shadow acne? Start it off the surface" : "")
                + (hint == null ? "" : "\nHINT: " + hint) + "\n";
    }

    // ---------------------------------------------------------------- colours

    /** Asserts a colour channel by channel (relative 1e-9; an expected 0 within 1e-12). */
    public static void color(String what, Color expected, Color actual, String hint) {
        if (actual == null || !close(expected.r, actual.r) || !close(expected.g, actual.g)
                || !close(expected.b, actual.b)) {
            fail(what + "\n  expected: " + expected + "\n  got:      " + actual
                    + (hint == null ? "" : "\nHINT: " + hint) + "\n");
        }
    }

    private static boolean close(double expected, double actual) {
        double tol = expected == 0 ? 1e-12 : TOL * Math.abs(expected);
        return Math.abs(expected - actual) <= tol;
    }

    // ---------------------------------------------------------------- vectors

    private static boolean close(Vec3 a, Vec3 b, double tol) {
        return Math.abs(a.x - b.x) <= tol && Math.abs(a.y - b.y) <= tol
                && Math.abs(a.z - b.z) <= tol;
    }

    private static double scale(Vec3 p, Vec3 x) {
        return Math.max(1, Math.max(p.maxAbs(), x.maxAbs()));
    }

    /** The unit vector along (x, y, z). */
    public static Vec3 unit(double x, double y, double z) {
        return new Vec3(x, y, z).normalize();
    }
}
