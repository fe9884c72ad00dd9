package raylab.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * The contract every {@code intersect} follows (handout 1), checked by {@code raylab trace} on the
 * surfaces one ray meets: the recorded t lies in [tMin, tMax]; a record is only overwritten by a
 * closer hit; the normal is unit length and a sphere's points out of it; true is returned exactly
 * when the record is written; no NaN anywhere. A broken rule is printed on the line where it
 * happens, after {@value #MARK}.
 */
final class ContractCheck {
    static final String MARK = "<-- BROKEN RULE: ";
    /** How far a unit normal's length may be from 1. */
    static final double UNIT = 1e-6;
    /** At most this many surfaces of a mesh are listed. */
    private static final int MAX_LINES = 20;

    private ContractCheck() {
    }

    /** "   <-- BROKEN RULE: rule", or "" when there is no rule. */
    static String flag(String rule) {
        return rule == null || rule.isEmpty() ? "" : "   " + MARK + rule;
    }

    /** The range rule for a recorded t, or null when it holds. */
    static String rangeRule(Ray ray, double t) {
        if (Double.isNaN(t)) {
            return "t is NaN: a recorded t must be a number in [tMin, tMax] (a negative discriminant?)";
        }
        if (ray.inRange(t)) {
            return null;
        }
        return "the recorded t = " + TraceCommand.num(t) + " must lie in [tMin, tMax] = [" + TraceCommand.num(ray.tMin)
                + ", " + TraceCommand.num(ray.tMax) + "]" + (t < ray.tMin ? ": a hit behind the ray's start does not count"
                        : ": a hit beyond tMax does not count");
    }

    /** The unit-length rule for a normal, or null when it holds. */
    static String unitRule(Vec3 n) {
        if (n == null) {
            return "no normal was recorded: outRecord.set(t, point, normal, this)";
        }
        String nan = nanRule("the normal", n);
        if (nan != null) {
            return nan;
        }
        double len = n.length();
        return Math.abs(len - 1) <= UNIT ? null
                : "the normal must be unit length, its length is " + TraceCommand.num(len) + " (normalize it)";
    }

    static String nanRule(String what, Vec3 v) {
        return v != null && (Double.isNaN(v.x) || Double.isNaN(v.y) || Double.isNaN(v.z))
                ? what + " has NaN in it: no value may be NaN (a square root of a negative number? 0/0?)" : null;
    }

    static String nanRule(String what, Color c) {
        return c != null && (Double.isNaN(c.r) || Double.isNaN(c.g) || Double.isNaN(c.b))
                ? what + " has NaN in it: no value may be NaN (0/0? a normal of length 0?)" : null;
    }

    /**
     * Asks each primitive of the scene in turn, as a group does, and prints every one's answer:
     * a hit at t (with the rules it breaks), an exception, or a miss and what made it one (the
     * same intersect asked again over all t: a hit before tMin or beyond tMax, farther than the
     * hit already recorded, t = NaN, or no hit at all), and when the ray lies in a box face's
     * plane (a slab) or in a triangle's plane.
     */
    static void walk(List<Surface> surfaces, Ray ray, PrintWriter out) {
        List<Surface> leaves = raylab.render.RenderPlan.primitives(surfaces);
        IntersectionRecord rec = new IntersectionRecord();
        List<String> answers = new ArrayList<>();
        List<String> misses = new ArrayList<>();
        List<String> inTurn = new ArrayList<>();
        int broken = 0;
        String firstBroken = null;
        java.util.List<String> files = null;
        for (Surface s : leaves) {
            IntersectionRecord before = new IntersectionRecord();
            before.copyFrom(rec);
            boolean returned;
            String plane = planeNote(s, ray);
            try {
                returned = s.intersect(rec, ray);
            } catch (RuntimeException | StackOverflowError e) {
                if (e instanceof raylab.course.NotImplemented n) {
                    throw n;
                }
                if (files == null) {
                    files = StudentFault.studentFiles(java.nio.file.Path.of("").toAbsolutePath());
                }
                inTurn.add("    \"" + s.name() + "\": " + StudentFault.describe(e, files, "").orElse("threw " + e)
                        + flag("intersect must not throw") + plane);
                answers.add(inTurn.get(inTurn.size() - 1));
                broken++;
                continue;
            }
            boolean wrote = Double.compare(rec.t, before.t) != 0 || rec.point != before.point || rec.normal != before.normal
                    || rec.surface != before.surface;
            if (!returned && !wrote && s instanceof raylab.surface.Box b && plane.contains("0/0") && meets(b, ray, before)) {
                // A missed box the ray meets along a face breaks a rule, whatever the probe over all t
                // says; the 0/0 of the face's plane is named as the cause only on evidence: the same
                // intersect hits the ray tilted off its d = 0 planes, into the box.
                boolean zeroOverZero = hitsTiltedInward(b, ray);
                inTurn.add("    \"" + s.name() + "\": miss" + flag("the ray meets this box (it runs along a face,"
                        + " inside the closed box) but intersect missed it: " + (zeroOverZero ? ZERO_OVER_ZERO
                                : notZeroOverZero(ray))) + plane);
                answers.add(inTurn.get(inTurn.size() - 1));
                firstBroken = firstBroken != null ? firstBroken : "\"" + s.name() + "\" is missed" + (zeroOverZero
                        ? " through 0/0: a slab with d = 0 and p on its plane" : ", and not through the 0/0 of its face");
                broken++;
                continue;
            }
            if (!returned && !wrote) {
                inTurn.add("    \"" + s.name() + "\": miss (" + whyMissed(s, ray, before) + ")" + plane);
                misses.add(inTurn.get(inTurn.size() - 1));
                continue;
            }
            List<String> rules = new ArrayList<>();
            if (returned != wrote) {
                rules.add(returned ? "returned true without writing the record: return true exactly when you write it"
                        : "wrote the record but returned false: return true exactly when you write it");
            }
            if (wrote) {
                String range = rangeRule(ray, rec.t);
                if (range != null) {
                    rules.add(range);
                }
                if (before.hasHit() && !(rec.t < before.t)) {
                    rules.add("the record held a closer hit (t = " + TraceCommand.num(before.t) + " on \""
                            + before.surface.name() + "\"): write only when t < outRecord.t");
                }
                String unit = unitRule(rec.normal);
                if (unit != null) {
                    rules.add(unit);
                }
                String nan = nanRule("the point", rec.point);
                if (nan != null) {
                    rules.add(nan);
                }
                for (raylab.scene.SurfaceType t : raylab.scene.SurfaceTypes.all().values()) {
                    String rule = t.traceRule(s, rec.point, rec.normal);
                    if (rule != null) {
                        rules.add(rule); // the sphere's: its normal points out of it
                    }
                }
            }
            broken += rules.isEmpty() ? 0 : 1;
            String what = wrote ? "hit at t = " + TraceCommand.num(rec.t) + ", normal " + TraceCommand.v(rec.normal == null
                    ? new Vec3(Double.NaN, Double.NaN, Double.NaN) : rec.normal) : "returned true";
            StringBuilder line = new StringBuilder("    \"" + s.name() + "\": " + what);
            for (int i = 0; i < rules.size(); i++) {
                line.append(i == 0 ? flag(rules.get(i)) : "; " + rules.get(i));
            }
            inTurn.add(line.append(plane).toString());
            answers.add(inTurn.get(inTurn.size() - 1));
        }
        // A missed box's cause is said here, before any line of the surfaces asked in turn.
        out.println("  surfaces asked in turn, as a group does (" + leaves.size() + ")" + (broken == 0
                ? ": every rule of intersect holds" : ": " + broken + " broke a rule of intersect"
                        + (firstBroken == null ? "" : " (" + firstBroken + ")")));
        if (inTurn.size() <= MAX_LINES) {
            inTurn.forEach(out::println); // in the order asked
            return;
        }
        // Many (a mesh): every hit and exception, then the first misses.
        List<String> lines = new ArrayList<>(answers);
        lines.addAll(misses);
        int shown = Math.max(MAX_LINES, answers.size());
        lines.stream().limit(shown).forEach(out::println);
        out.println("    ... and " + (lines.size() - shown) + " more misses");
    }

    /**
     * Why a surface returned false: its own intersect asked again with t over (-∞, ∞) and an
     * empty record says where its hit would be.
     */
    static String whyMissed(Surface s, Ray ray, IntersectionRecord held) {
        IntersectionRecord probe = new IntersectionRecord();
        boolean hit;
        try {
            hit = s.intersect(probe, new Ray(ray.p, ray.d, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY));
        } catch (RuntimeException | StackOverflowError e) {
            return "asked over all t, it throws " + e.getClass().getSimpleName();
        }
        if (Double.isNaN(probe.t)) {
            return "asked over all t, it records t = NaN";
        }
        if (!hit) {
            return "the line of the ray does not meet it";
        }
        double t = probe.t;
        if (t < ray.tMin) {
            return "its nearest hit over all t is at t = " + TraceCommand.num(t) + ", before tMin = "
                    + TraceCommand.num(ray.tMin);
        }
        if (t > ray.tMax) {
            return "its nearest hit over all t is at t = " + TraceCommand.num(t) + ", beyond tMax = "
                    + TraceCommand.num(ray.tMax);
        }
        if (held.hasHit() && t >= held.t) {
            return "its hit at t = " + TraceCommand.num(t) + " is not closer than the recorded t = "
                    + TraceCommand.num(held.t) + " on \"" + held.surface.name() + "\"";
        }
        return "although asked over all t it hits at t = " + TraceCommand.num(t) + ", inside [tMin, tMax]";
    }

    /**
     * Whether the ray meets the closed box within [tMin, tMax] and before a recorded hit: by slabs,
     * a slab with d = 0 decided without dividing (inside when min <= p <= max).
     */
    static boolean meets(raylab.surface.Box b, Ray ray, IntersectionRecord held) {
        double t0 = ray.tMin;
        double t1 = held.hasHit() ? Math.min(ray.tMax, held.t) : ray.tMax;
        for (int i = 0; i < 3; i++) {
            double d = ray.d.get(i);
            double p = ray.p.get(i);
            if (d == 0) {
                if (p < b.min.get(i) || p > b.max.get(i)) {
                    return false;
                }
                continue;
            }
            double a = (b.min.get(i) - p) / d;
            double c = (b.max.get(i) - p) / d;
            t0 = Math.max(t0, Math.min(a, c));
            t1 = Math.min(t1, Math.max(a, c));
        }
        return t0 <= t1;
    }

    /** Why a box the ray meets along a face was missed, when its d = 0 slabs alone break it. */
    static final String ZERO_OVER_ZERO = "a slab with d = 0 divides 0 by 0 (NaN) when p is on its plane; decide such"
            + " a slab without dividing (inside when min <= p <= max)";

    /**
     * Why such a box was missed when tilting the ray off its d = 0 planes does not help: not the
     * 0/0 of a face's plane; and, for a negative component of d, the slab's entry and exit.
     */
    static String notZeroOverZero(Ray ray) {
        String negative = ray.d.x < 0 ? "d.x" : ray.d.y < 0 ? "d.y" : ray.d.z < 0 ? "d.z" : null;
        return "it misses the ray tilted off that face into the box too, so the d = 0 slab (0/0) is not the cause;"
                + (negative == null ? " look at the slabs with d != 0"
                        : " " + negative + " < 0 here: a slab is entered at its max plane when d is negative"
                                + " (is t_min > t_max left unswapped?)");
    }

    /**
     * Whether the box's intersect hits the ray with every zero component of d tilted by a
     * thousandth of ‖d‖, toward the inside of the box where p is on a face's plane: evidence that
     * the zero components alone (the 0/0 of a slab) made it miss.
     */
    static boolean hitsTiltedInward(raylab.surface.Box b, Ray ray) {
        double tilt = 1e-3 * ray.d.length();
        double[] d = {ray.d.x, ray.d.y, ray.d.z};
        for (int i = 0; i < 3; i++) {
            if (d[i] == 0) {
                boolean onMax = ray.p.get(i) == b.max.get(i) && b.max.get(i) != b.min.get(i);
                d[i] = onMax ? -tilt : tilt;
            }
        }
        try {
            return b.intersect(new IntersectionRecord(), new Ray(ray.p, new Vec3(d[0], d[1], d[2]), ray.tMin, ray.tMax));
        } catch (RuntimeException | StackOverflowError e) {
            return false;
        }
    }

    /** "; the ray lies in the plane x = 1 of a face (a slab with d.x = 0)" and the like, or "". */
    static String planeNote(Surface s, Ray ray) {
        // Each surface type says what it knows (raylab.scene.SurfaceType.traceNote).
        StringBuilder note = new StringBuilder();
        for (raylab.scene.SurfaceType t : raylab.scene.SurfaceTypes.all().values()) {
            note.append(t.traceNote(s, ray));
        }
        return note.toString();
    }
}
