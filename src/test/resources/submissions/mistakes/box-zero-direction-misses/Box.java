// Mistake corpus (NoSilentLossTest): a ray with a zero direction component always misses.
package raylab.surface;

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
        // The lecture's slabs, computed with 1/d: a zero component gives an infinite 1/d, and the
        // slab's interval is then (−∞, +∞) when p lies between its planes and empty otherwise.
        // Only p exactly on a plane with d = 0 gives 0·∞ = NaN: the box is closed, so the ray is
        // inside that slab for every t.
        double enter = Double.NEGATIVE_INFINITY;
        double exit = Double.POSITIVE_INFINITY;
        int enterAxis = -1;
        int exitAxis = -1;
        for (int k = 0; k < 3; k++) {
            if (ray.d.get(k) == 0) {
                return false; // BUG: a zero direction component taken for a miss
            }
            double inv = 1 / ray.d.get(k);
            double t0 = (min.get(k) - ray.p.get(k)) * inv;
            double t1 = (max.get(k) - ray.p.get(k)) * inv;
            if (Double.isNaN(t0) || Double.isNaN(t1)) {
                continue; // in the plane of a face, moving along it: inside this slab for every t
            }
            double kEnter = Math.min(t0, t1);
            double kExit = Math.max(t0, t1);
            if (kEnter > enter) {
                enter = kEnter;
                enterAxis = k;
            }
            if (kExit < exit) {
                exit = kExit;
                exitAxis = k;
            }
        }
        if (enter > exit) {
            return false;
        }
        double t = enter;
        int axis = enterAxis;
        boolean entering = true;
        if (!ray.inRange(t) || t >= outRecord.t) {
            t = exit;
            axis = exitAxis;
            entering = false;
            if (!ray.inRange(t) || t >= outRecord.t) {
                return false;
            }
        }
        if (axis < 0) {
            return false;
        }
        // Entering through the min face when d > 0 (normal −e_k), the max face when d < 0;
        // leaving the other way round.
        double sign = (ray.d.get(axis) > 0) == entering ? -1 : 1;
        double[] n = new double[3];
        n[axis] = sign;
        outRecord.set(t, ray.evaluate(t), new Vec3(n[0], n[1], n[2]), this);
        return true;
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
