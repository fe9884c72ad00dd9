package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** A sphere with centre c and radius r: the points x with ‖x − c‖ = r. */
public class Sphere extends Surface {
    public final Vec3 center;
    public final double radius;

    public Sphere(Vec3 center, double radius, Material material, String name) {
        super(material, name);
        this.center = center;
        this.radius = radius;
    }

    /**
     * Ray–sphere intersection (milestone {@code sphere}).
     *
     * <p>Substituting r(t) = p + t·d into ‖x − c‖² = r² gives the quadratic
     * <pre>
     *   (d·d) t² + 2 d·(p − c) t + (p − c)·(p − c) − r² = 0
     *   t = ( −d·(p − c) ± √( (d·(p − c))² − (d·d)((p − c)·(p − c) − r²) ) ) / (d·d)
     * </pre>
     * d need not be a unit vector. If the nearer root is in the ray's range and closer than
     * {@code outRecord.t}, record it; otherwise try the farther root (the ray starts inside).
     * The normal to record is n = (x − c) / r, pointing out of the sphere.
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // f = p − c, kept exactly as the unevaluated sum fHi + fLo (Knuth's TwoSum), so that no
        // bits are lost when p and c are large and close together.
        Vec3 fHi = ray.p.minus(center);
        Vec3 fLo = new Vec3(twoSumError(ray.p.x, -center.x, fHi.x),
                twoSumError(ray.p.y, -center.y, fHi.y), twoSumError(ray.p.z, -center.z, fHi.z));
        // The quadratic is a t² − 2 b t + c = 0 with a = d·d, b = −f·d, c = f·f − r².
        double a = ray.d.dot(ray.d);
        double b = -(fHi.dot(ray.d) + fLo.dot(ray.d));
        // The discriminant as r² − ‖f + (b/a) d‖², the squared distance from the line to the
        // centre: this avoids the cancellation of b² − a·c for rays that pass far away.
        Vec3 perp = fHi.plus(ray.d.times(b / a)).plus(fLo);
        double disc = radius * radius - perp.lengthSquared();
        if (disc < 0) {
            return false;
        }
        // c = ‖f‖² − r² nearly cancels when p is just outside a large sphere: sum it compensated.
        double c = lengthSquaredMinusSquare(fHi, fLo, radius);
        // Both roots without subtracting nearly equal numbers: q = b + sign(b)·√(a·disc).
        double q = b + Math.copySign(Math.sqrt(a * disc), b);
        double t0 = q == 0 ? 0 : c / q;
        double t1 = q / a;
        if (t0 > t1) {
            double swap = t0;
            t0 = t1;
            t1 = swap;
        }
        double t = t1; // BUG: the farther root first
        if (!ray.inRange(t) || t >= outRecord.t) {
            t = t0;
            if (!ray.inRange(t) || t >= outRecord.t) {
                return false;
            }
        }
        // Project the computed point back onto the sphere, which removes most of its error.
        Vec3 fromCenter = ray.evaluate(t).minus(center);
        Vec3 normal = fromCenter.normalize();
        outRecord.set(t, center.plus(normal.times(radius)), normal, this);
        return true;
    }

    /** The rounding error of s = fl(x + y), so that x + y = s + error exactly (Knuth's TwoSum). */
    private static double twoSumError(double x, double y, double s) {
        double yVirtual = s - x;
        return (x - (s - yVirtual)) + (y - yVirtual);
    }

    /**
     * ‖fHi + fLo‖² − r² without cancellation: each square is split exactly into its rounded value
     * and its rounding error (with an FMA), the tiny fLo² is dropped, and all the parts are added
     * with Neumaier's compensated summation.
     */
    private static double lengthSquaredMinusSquare(Vec3 fHi, Vec3 fLo, double r) {
        double[] parts = new double[11];
        for (int axis = 0; axis < 3; axis++) {
            double h = fHi.get(axis);
            double square = h * h;
            parts[3 * axis] = square;
            parts[3 * axis + 1] = Math.fma(h, h, -square);
            parts[3 * axis + 2] = 2 * h * fLo.get(axis);
        }
        double rr = r * r;
        parts[9] = -rr;
        parts[10] = -Math.fma(r, r, -rr);
        double sum = 0;
        double compensation = 0;
        for (double part : parts) {
            double next = sum + part;
            compensation += Math.abs(sum) >= Math.abs(part) ? (sum - next) + part
                    : (part - next) + sum;
            sum = next;
        }
        return sum + compensation;
    }

    @Override
    public BoundingBox boundingBox() {
        Vec3 r = new Vec3(radius, radius, radius);
        return new BoundingBox(center.minus(r), center.plus(r));
    }

    @Override
    public boolean isConvex() {
        return true;
    }
}
