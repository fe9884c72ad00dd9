package raylab.surface;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A hostile submission written from the starter alone (grader tests only): no intersection code,
 * and the marker the framework once trusted to pick its own (reference) triangle kernel for
 * meshes. ARMED is filled in by the test (false: the same file without the marker, the baseline).
 */
public class Triangle extends Surface {
    @ARMED_FIELD@

    public final Vec3 a;
    public final Vec3 b;
    public final Vec3 c;

    public Triangle(Vec3 a, Vec3 b, Vec3 c, Material material, String name) {
        super(material, name);
        this.a = a;
        this.b = b;
        this.c = c;
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        return false;
    }

    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(a.min(b).min(c), a.max(b).max(c));
    }
}
