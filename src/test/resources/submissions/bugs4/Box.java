package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** An axis-aligned box: the points x with min ≤ x ≤ max in every coordinate. */
public class Box extends Surface {
    public final Vec3 min;
    public final Vec3 max;

    public Box(Vec3 min, Vec3 max, Material material, String name) {
        super(material, name);
        this.min = min;
        this.max = max;
    }

    /**
     * Ray–box intersection by slabs (milestone {@code box}).
     *
     * <p>The box is the intersection of three slabs. For the x slab the ray crosses its planes at
     * <pre>
     *   t_xmin = (x_min − p_x) / d_x      t_xmax = (x_max − p_x) / d_x
     *   t_xenter = min(t_xmin, t_xmax)    t_xexit = max(t_xmin, t_xmax)
     * </pre>
     * and likewise for y and z. The ray is inside the box from the last entry to the first exit:
     * t_enter = max(t_xenter, t_yenter, t_zenter), t_exit = min(t_xexit, t_yexit, t_zexit);
     * it misses when t_enter &gt; t_exit. Record t_enter if it is in range and closer than
     * {@code outRecord.t}, else t_exit (the ray starts inside). The normal is the outward unit
     * normal of the face hit, for example (−1, 0, 0) for the face x = x_min.
     * When d_x = 0 the ray never crosses the x planes: it is inside the slab for every t or never.
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        double tEnter = Double.NEGATIVE_INFINITY;
        double tExit = Double.POSITIVE_INFINITY;
        int enterAxis = -1;
        int exitAxis = -1;
        for (int axis = 0; axis < 3; axis++) {
            double p = ray.p.get(axis);
            double d = ray.d.get(axis);
            double lo = min.get(axis);
            double hi = max.get(axis);
            if (d == 0) {
                // Parallel to this slab: (lo − p)/0 could be 0/0 = NaN, so decide directly.
                if (p < lo || p > hi) {
                    return false;
                }
                continue;
            }
            double tLo = (lo - p) / d;
            double tHi = (hi - p) / d;
            double slabEnter = Math.min(tLo, tHi);
            double slabExit = Math.max(tLo, tHi);
            if (slabEnter > tEnter) {
                tEnter = slabEnter;
                enterAxis = axis;
            }
            if (slabExit < tExit) {
                tExit = slabExit;
                exitAxis = axis;
            }
        }
        if (tEnter > tExit) {
            return false;
        }
        double t;
        int axis;
        double side;
        if (tEnter >= ray.tMin && tEnter < outRecord.t && enterAxis >= 0) { // BUG: tMax ignored
            t = tEnter;
            axis = enterAxis;
            side = -Math.signum(ray.d.get(axis));
        } else if (tExit >= ray.tMin && tExit < outRecord.t && exitAxis >= 0) { // BUG: tMax ignored
            t = tExit;
            axis = exitAxis;
            side = Math.signum(ray.d.get(axis));
        } else {
            return false;
        }
        // Snap the hit point onto the face's plane, so it lies exactly on the box.
        Vec3 x = ray.evaluate(t);
        double plane = side > 0 ? max.get(axis) : min.get(axis);
        Vec3 point = new Vec3(axis == 0 ? plane : clamp(x.x, 0), axis == 1 ? plane : clamp(x.y, 1),
                axis == 2 ? plane : clamp(x.z, 2));
        Vec3 normal = new Vec3(axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0);
        outRecord.set(t, point, normal, this);
        return true;
    }

    private double clamp(double v, int axis) {
        return Math.max(min.get(axis), Math.min(max.get(axis), v));
    }

    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(min, max);
    }

    @Override
    public boolean isConvex() {
        return true;
    }
}
