package raylab.numerics;

import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;

/** Ray–box methods to compare with the reference {@link Box#intersect}. */
public final class BoxMethods {
    private BoxMethods() {
    }

    /**
     * The lecture's slabs as written: t = (lo − p)/d for every axis, Math.min/Math.max, no
     * special case for d = 0, the point p + t·d. When p lies exactly on a slab plane and d is
     * zero along that axis, (lo − p)/d = 0/0 = NaN; Math.min and Math.max pass the NaN on, every
     * comparison with it is false, and the ray is reported as a miss although it runs along the
     * box's face (or edge).
     */
    public static boolean naiveSlabs(Box box, IntersectionRecord rec, Ray ray) {
        double tEnter = Double.NEGATIVE_INFINITY;
        double tExit = Double.POSITIVE_INFINITY;
        int enterAxis = 0;
        int exitAxis = 0;
        for (int axis = 0; axis < 3; axis++) {
            double p = ray.p.get(axis);
            double d = ray.d.get(axis);
            double tLo = (box.min.get(axis) - p) / d;
            double tHi = (box.max.get(axis) - p) / d;
            double slabEnter = Math.min(tLo, tHi);
            double slabExit = Math.max(tLo, tHi);
            if (axis == 0 || Math.max(tEnter, slabEnter) != tEnter) {
                enterAxis = axis;
            }
            if (axis == 0 || Math.min(tExit, slabExit) != tExit) {
                exitAxis = axis;
            }
            tEnter = Math.max(tEnter, slabEnter);
            tExit = Math.min(tExit, slabExit);
        }
        if (tEnter > tExit) {
            return false;
        }
        double t;
        int axis;
        double side;
        if (ray.inRange(tEnter) && tEnter < rec.t) {
            t = tEnter;
            axis = enterAxis;
            side = -Math.signum(ray.d.get(axis));
        } else if (ray.inRange(tExit) && tExit < rec.t) {
            t = tExit;
            axis = exitAxis;
            side = Math.signum(ray.d.get(axis));
        } else {
            return false;
        }
        Vec3 normal = new Vec3(axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0);
        rec.set(t, ray.evaluate(t), normal, box);
        return true;
    }

    /** The reference method, {@link Box#intersect}. */
    public static boolean reference(Box box, IntersectionRecord rec, Ray ray) {
        return box.intersect(rec, ray);
    }

    public static Intersector naiveSlabs(Box box) {
        return (rec, ray) -> naiveSlabs(box, rec, ray);
    }

    public static Intersector reference(Box box) {
        return (rec, ray) -> reference(box, rec, ray);
    }
}
