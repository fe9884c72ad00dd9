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
        // Inverse direction; swap when it is negative; remember the axis of entry and exit.
        double tNear = Double.NEGATIVE_INFINITY;
        double tFar = Double.POSITIVE_INFINITY;
        int nearAxis = 0;
        int farAxis = 0;
        for (int k = 0; k < 3; k++) {
            double inv = 1.0 / ray.d.get(k);
            double t0 = (min.get(k) - ray.p.get(k)) * inv;
            double t1 = (max.get(k) - ray.p.get(k)) * inv;
            if (inv < 0) {
                double s = t0;
                t0 = t1;
                t1 = s;
            }
            if (t0 > tNear) {
                tNear = t0;
                nearAxis = k;
            }
            if (t1 < tFar) {
                tFar = t1;
                farAxis = k;
            }
        }
        if (tNear > tFar) {
            return false;
        }
        double t;
        Vec3 n;
        if (ray.inRange(tNear) && tNear < outRecord.t) {
            t = tNear;
            n = axis(nearAxis, ray.d.get(nearAxis) > 0 ? -1 : 1);
        } else if (ray.inRange(tFar) && tFar < outRecord.t) {
            t = tFar;
            n = axis(farAxis, ray.d.get(farAxis) > 0 ? 1 : -1);
        } else {
            return false;
        }
        outRecord.set(t, ray.evaluate(t), n, this);
        return true;
    }

    private static Vec3 axis(int k, double s) {
        return new Vec3(k == 0 ? s : 0, k == 1 ? s : 0, k == 2 ? s : 0);
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
