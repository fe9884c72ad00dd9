package raylab.surface;

import java.util.List;

import raylab.math.BoundingBox;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A triangle mesh, such as one loaded from an OBJ file: its triangles share one material and are
 * traced through their own bounding volume hierarchy.
 */
public final class Mesh extends Surface {
    private final List<Triangle> triangles;
    private final Bvh bvh;

    public Mesh(List<Triangle> triangles, String name) {
        super(triangles.isEmpty() ? null : triangles.get(0).material(), name);
        this.triangles = List.copyOf(triangles);
        this.bvh = new Bvh(triangles, name);
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        return bvh.intersect(outRecord, ray);
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        return bvh.intersectsAny(ray, scratch);
    }

    @Override
    public BoundingBox boundingBox() {
        return bvh.boundingBox();
    }

    @Override
    public int primitiveCount() {
        return triangles.size();
    }

    /** The triangles, in file order. */
    public List<Triangle> triangles() {
        return triangles;
    }
}
