// Lecture method corpus (LectureMethodsTest): six separate face tests. Written from the lecture and the handout, graded to 100.
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
        // The lecture's first idea: intersect the six faces one by one. Face k = min_k or max_k is
        // a plane; the ray meets it at t = (v − p_k) / d_k (never when d_k = 0), and the point is
        // on the face when its other two coordinates lie within the box (closed). The nearest
        // such t in range wins.
        double best = outRecord.t;
        Vec3 bestNormal = null;
        for (int k = 0; k < 3; k++) {
            double dk = ray.d.get(k);
            if (dk == 0) {
                continue;
            }
            for (int side = 0; side < 2; side++) {
                double v = side == 0 ? min.get(k) : max.get(k);
                double t = (v - ray.p.get(k)) / dk;
                if (!ray.inRange(t) || t >= best) {
                    continue;
                }
                Vec3 x = ray.evaluate(t);
                boolean onFace = true;
                for (int j = 0; j < 3; j++) {
                    if (j != k && (x.get(j) < min.get(j) || x.get(j) > max.get(j))) {
                        onFace = false;
                    }
                }
                if (onFace) {
                    best = t;
                    double[] n = new double[3];
                    n[k] = side == 0 ? -1 : 1;
                    bestNormal = new Vec3(n[0], n[1], n[2]);
                }
            }
        }
        if (bestNormal == null) {
            return false;
        }
        outRecord.set(best, ray.evaluate(best), bestNormal, this);
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
