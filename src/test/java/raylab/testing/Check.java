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

    // ---------------------------------------------------------------- hints chosen by evidence

    /**
     * What a failed check saw, for deciding which hint applies.
     *
     * @param problem  "no hit", "wrong t", "wrong point", "wrong normal", "unexpected hit", ...
     * @param ray      the ray (null for colour checks)
     * @param expected the expected normal (null when none)
     * @param got      the recorded normal (null when none)
     */
    public record Failure(String problem, Ray ray, Vec3 expected, Vec3 got) {
        /** A hit where a miss was expected, a miss where a hit was, or the wrong t. */
        public boolean hitOrT() {
            return problem.equals("no hit") || problem.equals("wrong t") || problem.equals("unexpected hit");
        }

        /** Whether d has an exactly zero component. */
        public boolean zeroComponent() {
            return ray != null && (ray.d.x == 0 || ray.d.y == 0 || ray.d.z == 0);
        }
    }

    /**
     * A hint that names one mistake, shown only when the failing case's data match it: a hint
     * about d_x = 0 only for a wrong hit, miss or t of a ray with a zero component, a hint about
     * the normal only for a wrong normal. A plain string hint is shown with any failure.
     */
    public record Hint(String text, java.util.function.Predicate<Failure> when) {
        /** The d = 0 hint: a wrong hit, miss or t, and the ray has a zero direction component. */
        public static Hint zeroComponent(String text) {
            return new Hint(text, f -> f.hitOrT() && f.zeroComponent());
        }

        /** A hint about the normal: the hit was right, its normal was not. */
        public static Hint normal(String text) {
            return new Hint(text, f -> f.problem().equals("wrong normal"));
        }

        /** A hint about whether it hits: a miss where a hit was expected, or a hit where none was. */
        public static Hint hitOrMiss(String text) {
            return new Hint(text, f -> f.problem().equals("no hit") || f.problem().equals("unexpected hit"));
        }

        String shownFor(Failure f) {
            return when.test(f) ? text : null;
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

    /** The same, with a hint shown only when the failure matches it. */
    public static IntersectionRecord hitWhen(Surface s, Ray ray, double t, Vec3 point, Vec3 normal, Hint hint) {
        return hitWith(new IntersectionRecord(), s, ray, t, point, normal, hint);
    }

    /** The same, starting from a given record (for example one that holds a farther hit). */
    public static IntersectionRecord hit(IntersectionRecord rec, Surface s, Ray ray, double t,
            Vec3 point, Vec3 normal, String hint) {
        return hitWith(rec, s, ray, t, point, normal, hint == null ? null : new Hint(hint, f -> true));
    }

    private static IntersectionRecord hitWith(IntersectionRecord rec, Surface s, Ray ray, double t,
            Vec3 point, Vec3 normal, Hint hint) {
        double recordT = rec.t;
        boolean returned = intersect(s, rec, ray);
        String expected = "hit at t=" + t + ", point " + point + ", normal " + normal;
        boolean wrote = rec.t != recordT;
        if (!returned || !wrote) {
            boolean neither = !returned && !wrote;
            String why = neither ? "no hit"
                    : returned ? "returned true but did not write the record"
                    : "wrote the record but returned false";
            String auto = neither ? (s instanceof Triangle tri ? edgeHint(tri, point)
                    : s instanceof Box && hint == null && zeroAxes(ray) != null ? boxHint(s, ray)
                            : insideHint(s, ray))
                    : "return true exactly when you write the record";
            fail(message(why, s, ray, expected, rec, returned, auto,
                    hint == null ? null : hint.shownFor(new Failure(neither ? "no hit" : why, ray, normal, rec.normal))));
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
            fail(message(problem, s, ray, expected, rec, returned, auto,
                    hint == null ? null : hint.shownFor(new Failure(problem, ray, normal, rec.normal))));
        }
        return rec;
    }

    /**
     * The hint for a box that misses a ray with a zero direction component, on evidence: the d = 0
     * hint only when the same box hits the ray tilted off those planes (so the zero components
     * alone break it); when it misses that too and d has a negative component, the swap of the
     * slab's entry and exit; otherwise none.
     */
    static String boxHint(Surface s, Ray ray) {
        double tilt = 1e-3 * ray.d.length();
        Ray tilted = new Ray(ray.p, new Vec3(ray.d.x == 0 ? tilt : ray.d.x, ray.d.y == 0 ? tilt : ray.d.y,
                ray.d.z == 0 ? tilt : ray.d.z), ray.tMin, ray.tMax);
        if (intersect(s, new IntersectionRecord(), tilted)) {
            return zeroAxes(ray) + " here: the ray never crosses those planes. It is inside such a slab for"
                    + " every t when min ≤ p ≤ max (the box is closed), outside for every t otherwise:"
                    + " decide that without dividing (when p is on a plane, (min − p)/0 = 0/0 = NaN)";
        }
        String negative = ray.d.x < 0 ? "d_x" : ray.d.y < 0 ? "d_y" : ray.d.z < 0 ? "d_z" : null;
        return negative == null ? insideHint(s, ray) : negative + " < 0 here, and the box is missed even with the"
                + " ray tilted off the planes of its zero components: when d is negative, a slab is entered at its"
                + " max plane and left at its min plane: swap t_min and t_max when t_min > t_max";
    }

    /** "d_x = 0" (or "d_x = d_y = 0") for the zero components of d, or null when there are none. */
    static String zeroAxes(Ray ray) {
        StringBuilder b = new StringBuilder();
        String[] names = {"d_x", "d_y", "d_z"};
        for (int k = 0; k < 3; k++) {
            if (ray.d.get(k) == 0) {
                b.append(names[k]).append(" = ");
            }
        }
        return b.length() == 0 ? null : b.append("0").toString();
    }

    /**
     * For a triangle that was missed: where the expected point lies against the three edges
     * a → b → c → a. Strictly inside all three: one of the edge tests is the wrong way round
     * (or uses another n). Exactly on an edge or a vertex: the closed triangle's ≥ 0.
     */
    public static String edgeHint(Triangle tri, Vec3 x) {
        Vec3 n = tri.b.minus(tri.a).cross(tri.c.minus(tri.a));
        double[] e = {
            tri.b.minus(tri.a).cross(x.minus(tri.a)).dot(n),
            tri.c.minus(tri.b).cross(x.minus(tri.b)).dot(n),
            tri.a.minus(tri.c).cross(x.minus(tri.c)).dot(n)};
        String[] names = {"ab", "bc", "ca"};
        StringBuilder zero = new StringBuilder();
        boolean inside = true;
        for (int i = 0; i < 3; i++) {
            if (e[i] == 0) {
                zero.append(zero.length() == 0 ? "" : " and ").append(names[i]);
            }
            inside &= e[i] > 0;
        }
        if (inside) {
            return "the expected point x = " + x + " is strictly inside all three edges (((b − a) × (x − a))·n = "
                    + fmt(e[0]) + ", ((c − b) × (x − b))·n = " + fmt(e[1]) + ", ((a − c) × (x − c))·n = " + fmt(e[2])
                    + ", all > 0): a miss here means an edge test written the other way round (go round a → b → c → a,"
                    + " each edge as (next − this) × (x − this)) or an n other than (b − a) × (c − a)";
        }
        if (zero.length() > 0) {
            return "the expected point x = " + x + " lies exactly on the edge " + zero + " (an edge test of exactly 0):"
                    + " the triangle is closed, so the inside-edge tests are ≥ 0, not > 0";
        }
        return null;
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    /** Asserts that {@code s} does not hit {@code ray}: returns false, record left empty. */
    public static void miss(Surface s, Ray ray, String hint) {
        untouched(new IntersectionRecord(), s, ray, hint);
    }

    /** The same, with a hint shown only when the failure matches it. */
    public static void missWhen(Surface s, Ray ray, Hint hint) {
        untouchedWhen(new IntersectionRecord(), s, ray, hint);
    }

    /** {@link #untouched(IntersectionRecord, Surface, Ray, String)} with a hint chosen by evidence. */
    public static void untouchedWhen(IntersectionRecord rec, Surface s, Ray ray, Hint hint) {
        try {
            untouched(rec, s, ray, (String) null);
        } catch (AssertionError e) {
            String shown = hint == null ? null : hint.shownFor(new Failure("unexpected hit", ray, null, rec.normal));
            throw shown == null ? e : new AssertionError(e.getMessage().stripTrailing() + "\nHINT: " + shown + "\n");
        }
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
        controlHit(s);
    }

    /**
     * The control that a miss is scored with: the same code must hit the surface where a ray
     * from outside, at an oblique angle with every component of d positive, passes through its
     * centre (a sphere's centre, a box's centre, a triangle's centroid), with a t in the ray's
     * range written to a fresh record. For a triangle a hit just outside the midpoint of one of
     * its edges counts too (code with one edge test the wrong way round hits there and not at the
     * centroid: it computes something, it is not a constant). Code that always misses passes
     * every miss on its own; with the control it earns nothing for them. The exact t is the hit
     * tests' business: here any hit counts. Surfaces of other kinds have no control.
     */
    public static void controlHit(Surface s) {
        java.util.List<Ray> controls = controlRays(s);
        if (controls.isEmpty()) {
            return;
        }
        IntersectionRecord first = null;
        boolean firstReturned = false;
        for (Ray control : controls) {
            IntersectionRecord rec = new IntersectionRecord();
            double before = rec.t;
            boolean returned = intersect(s, rec, control);
            if (returned && rec.t != before && control.inRange(rec.t)) {
                return;
            }
            if (first == null) {
                first = rec;
                firstReturned = returned;
            }
        }
        fail(message("no hit on the control ray", s, controls.get(0),
                "a hit: this ray passes through the centre of the surface from outside (a test of a miss counts"
                        + " only when the same code hits the surface where it must)", first, firstReturned,
                firstReturned ? "return true exactly when you write the record" : null));
    }

    /**
     * The control rays of {@link #controlHit}: the first through the centre, from outside, with
     * every component of d positive (no zero component, no negative one); for a triangle then one
     * just outside the midpoint of each edge. Empty for a degenerate or unknown surface.
     */
    public static java.util.List<Ray> controlRays(Surface s) {
        Vec3 out = new Vec3(0.36, 0.48, 0.8);
        if (s instanceof Sphere sp) {
            double size = Math.abs(sp.radius);
            return size > 0 && Double.isFinite(size) ? java.util.List.of(toward(sp.center, out, size))
                    : java.util.List.of();
        } else if (s instanceof Box b) {
            if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z)) {
                return java.util.List.of(); // flat or empty: no centre to aim at
            }
            double size = b.max.minus(b.min).length();
            return Double.isFinite(size) ? java.util.List.of(toward(b.min.plus(b.max).times(0.5), out, size))
                    : java.util.List.of();
        } else if (s instanceof Triangle tr) {
            Vec3 n = tr.b.minus(tr.a).cross(tr.c.minus(tr.a));
            double size = Math.max(tr.b.minus(tr.a).length(), tr.c.minus(tr.a).length());
            if (!(n.length() > 0) || !Double.isFinite(size)) {
                return java.util.List.of(); // degenerate: nothing to hit
            }
            // Mostly along the normal (whichever side has n·d < 0), tilted so that no component of d is zero.
            Vec3 along = n.normalize().plus(new Vec3(0.03, 0.05, 0.07));
            Vec3 g = tr.a.plus(tr.b).plus(tr.c).times(1.0 / 3);
            java.util.List<Ray> rays = new java.util.ArrayList<>();
            rays.add(toward(g, along.negate(), size));
            for (Vec3[] edge : new Vec3[][] {{tr.a, tr.b}, {tr.b, tr.c}, {tr.c, tr.a}}) {
                Vec3 m = edge[0].plus(edge[1]).times(0.5);
                rays.add(toward(m.plus(m.minus(g).times(0.25)), along.negate(), size));
            }
            return rays;
        }
        return java.util.List.of();
    }

    /** A ray that travels along d (scaled to 3·size) and reaches x at t = 1. */
    private static Ray toward(Vec3 x, Vec3 d, double size) {
        Vec3 step = d.times(3 * size / d.length());
        return new Ray(x.minus(step), step);
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
        shadowControl(scene, x, n, light);
    }

    /**
     * The control that "lit" is scored with: the same scene, point and light with a ball added
     * halfway between x and the light (radius a quarter of their distance, so it touches neither)
     * must shadow x. Code that always answers "lit" passes every lit case on its own; with the
     * control it earns nothing for them. Nothing is asked of a light that casts no shadows.
     */
    public static void shadowControl(Surface scene, Vec3 x, Vec3 n, PointLight light) {
        double distance = light.position.minus(x).length();
        if (!light.castsShadows || !(distance > 0) || !Double.isFinite(distance)) {
            return;
        }
        Sphere ball = new Sphere(x.plus(light.position).times(0.5), distance / 4,
                new Lambertian(Color.WHITE, Color.BLACK, "control material"), "control ball");
        Surface withBall = new raylab.surface.Group(java.util.List.of(scene, ball), "scene and control ball");
        IntersectionRecord scratch = new IntersectionRecord();
        if (!raylab.shading.Shadows.isShadowed(withBall, x, n, light, scratch)) {
            fail(shadowMessage("not shadowed by the control ball", x, n, light, "shadowed by the control ball "
                    + describe(ball) + ", added halfway between x and the light (a test of a lit point counts only"
                    + " when the same code finds a blocker where there is one)", false, scratch, null));
        }
    }

    /**
     * The control that "shadowed" is scored with: the same point and light in an empty scene must
     * be lit. Code that always answers "shadowed" passes every shadowed case on its own; with the
     * control it earns nothing for them.
     */
    public static void litControl(Vec3 x, Vec3 n, PointLight light) {
        Surface empty = new raylab.surface.Group(java.util.List.of(), "empty scene");
        IntersectionRecord scratch = new IntersectionRecord();
        if (raylab.shading.Shadows.isShadowed(empty, x, n, light, scratch)) {
            fail(shadowMessage("shadowed in an empty scene", x, n, light, "lit: the control scene is empty, nothing can"
                    + " block the light (a test of a shadow counts only when the same code finds the light where"
                    + " nothing blocks it)", true, scratch, null));
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

    /**
     * A colour a named mistake gives in this case, with the hint that names it: shown only when
     * the colour that came back is that one.
     */
    public record Likely(Color wouldBe, String hint) {
    }

    /**
     * Asserts a colour; on failure, the hints of the mistakes whose colour came back (none when
     * the colour matches no named mistake: then the message only says expected and got).
     */
    public static void colorLikely(String what, Color expected, Color actual, Likely... likely) {
        if (actual != null && close(expected.r, actual.r) && close(expected.g, actual.g) && close(expected.b, actual.b)) {
            return;
        }
        StringBuilder hints = new StringBuilder();
        for (Likely l : likely) {
            if (actual != null && close(l.wouldBe().r, actual.r) && close(l.wouldBe().g, actual.g)
                    && close(l.wouldBe().b, actual.b)) {
                hints.append("\nHINT: ").append(l.hint());
            }
        }
        fail(what + "\n  expected: " + expected + "\n  got:      " + actual + hints + "\n");
    }

    /** Asserts a colour channel by channel (relative 1e-9; an expected 0 within 1e-12). */
    public static void color(String what, Color expected, Color actual, String hint) {
        if (actual == null || !close(expected.r, actual.r) || !close(expected.g, actual.g)
                || !close(expected.b, actual.b)) {
            fail(what + "\n  expected: " + expected + "\n  got:      " + actual
                    + (hint == null ? "" : "\nHINT: " + hint) + "\n");
        }
    }

    /**
     * The control that a black diffuse answer is scored with: kd = (0.5, 0.25, 1) lit straight
     * from above (n = l, so n·l = 1) gives L_d = kd·I, for I = 1 and again for I = 2. A constant
     * colour cannot pass both; black fails both.
     */
    public static void diffuseControl() {
        Lambertian m = new Lambertian(new Color(0.5, 0.25, 1), Color.BLACK, "control matte");
        Vec3 n = new Vec3(0, 0, 1);
        color("control: diffuse with n = l = (0,0,1), kd = (0.5,0.25,1), I = (1,1,1) (a case of black counts only when"
                + " the same code lights a surface facing the light)", new Color(0.5, 0.25, 1),
                m.diffuse(n, n, new Color(1, 1, 1)), null);
        color("control: diffuse with n = l = (0,0,1), kd = (0.5,0.25,1), I = (2,2,2)", new Color(1, 0.5, 2),
                m.diffuse(n, n, new Color(2, 2, 2)), null);
    }

    /**
     * The control that a black (or constant) highlight is scored with: ks = (0.5, 0.25, 1) seen and
     * lit along n (h = n, the full highlight) must give a highlight that is not black, and twice
     * the light, I = 2 instead of 1, must give twice it (L_s = ks·I·max(0, n·h)^p is linear in
     * I). A constant colour fails: black is black, any other constant does not double. What the
     * highlight is exactly is the other tests' business.
     */
    public static void specularControl() {
        raylab.material.BlinnPhong m = new raylab.material.BlinnPhong(Color.BLACK, new Color(0.5, 0.25, 1), 10,
                Color.BLACK, "control shiny");
        Vec3 n = new Vec3(0, 0, 1);
        Color once = m.specular(n, n, n, new Color(1, 1, 1));
        Color twice = m.specular(n, n, n, new Color(2, 2, 2));
        String what = "control: specular with n = l = v = (0,0,1), ks = (0.5,0.25,1), p = 10 (a case of black or of two"
                + " equal highlights counts only when the same code shows a highlight that grows with the light)";
        if (once == null || !(once.r > 0 || once.g > 0 || once.b > 0)) {
            fail(what + "\n  expected: a highlight (not black) for I = (1,1,1)\n  got:      " + once + "\n");
        }
        color(what + ", I = (2,2,2) against I = (1,1,1)", new Color(2 * once.r, 2 * once.g, 2 * once.b), twice,
                "L_s = ks·I·max(0, n·h)^p: twice the light gives twice the highlight");
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
