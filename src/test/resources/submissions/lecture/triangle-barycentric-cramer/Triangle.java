// Lecture method corpus (LectureMethodsTest): barycentric coordinates by Cramer’s rule. Written from the lecture and the handout, graded to 100.
package raylab.surface;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The triangle with vertices a, b, c. Its normal n = (b − a) × (c − a) / ‖(b − a) × (c − a)‖
 * points to the side from which a, b, c are seen counter-clockwise.
 */
public class Triangle extends Surface {
    public final Vec3 a;
    public final Vec3 b;
    public final Vec3 c;

    public Triangle(Vec3 a, Vec3 b, Vec3 c, Material material, String name) {
        super(material, name);
        this.a = a;
        this.b = b;
        this.c = c;
    }

    /**
     * Ray–triangle intersection (milestone {@code triangle}).
     *
     * <p>First the plane: with n = (b − a) × (c − a), the ray meets the plane (x − a)·n = 0 at
     * <pre>
     *   t = (a − p)·n / (d·n)          (no hit when d·n = 0: the ray is parallel to the plane)
     * </pre>
     * Then the point x = p + t·d is inside the triangle when it is on the inner side of all three
     * edges:
     * <pre>
     *   ((b − a) × (x − a))·n ≥ 0,   ((c − b) × (x − b))·n ≥ 0,   ((a − c) × (x − c))·n ≥ 0
     * </pre>
     * Record the hit if t is in range and closer than {@code outRecord.t}, with the unit normal
     * n / ‖n‖ (whichever side the ray comes from).
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // The linear system the lecture points to (Shirley): a + β(b − a) + γ(c − a) = p + t·d,
        // i.e. β(a − b) + γ(a − c) + t·d = a − p, solved by Cramer's rule. Inside when β ≥ 0,
        // γ ≥ 0 and β + γ ≤ 1.
        Vec3 e1 = a.minus(b);
        Vec3 e2 = a.minus(c);
        Vec3 r = a.minus(ray.p);
        double det = det(e1, e2, ray.d);
        if (det == 0) {
            return false;
        }
        double beta = det(r, e2, ray.d) / det;
        double gamma = det(e1, r, ray.d) / det;
        double t = det(e1, e2, r) / det;
        if (!ray.inRange(t) || t >= outRecord.t) {
            return false;
        }
        if (beta < 0 || gamma < 0 || beta + gamma > 1) {
            return false;
        }
        outRecord.set(t, ray.evaluate(t), b.minus(a).cross(c.minus(a)).normalize(), this);
        return true;
    }


    /** The determinant of the 3×3 matrix with columns u, v, w: u · (v × w). */
    private static double det(Vec3 u, Vec3 v, Vec3 w) {
        return u.dot(v.cross(w));
    }

    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(a.min(b).min(c), a.max(b).max(c));
    }
}
