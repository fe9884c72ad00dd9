package raylab.surface;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * Anything a ray can hit: a single shape, or a group of surfaces.
 *
 * <p>The contract of {@link #intersect}: look for the closest hit with t in the ray's range
 * [tMin, tMax]; if it exists and is closer than {@code outRecord.t}, write it to the record and
 * return true; otherwise leave the record exactly as it was and return false.
 */
public abstract class Surface {
    private final Material material;
    private final String name;

    protected Surface(Material material, String name) {
        this.material = material;
        this.name = name;
    }

    /** The material that shades this surface (null for groups, whose members have their own). */
    public Material material() {
        return material;
    }

    /** A name for messages and ray trees, such as "sphere #2" or the name given in the scene. */
    public String name() {
        return name;
    }

    /**
     * Closest hit: updates {@code outRecord} only with a hit in the ray's range that is closer
     * than {@code outRecord.t}, and says whether it did.
     */
    public abstract boolean intersect(IntersectionRecord outRecord, Ray ray);

    /**
     * Any hit in the ray's range, for shadow rays: true as soon as one is known. Cheaper than
     * {@link #intersect} for groups, which may stop at the first blocker. The scratch record is
     * overwritten.
     */
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        scratch.reset();
        return intersect(scratch, ray);
    }

    /** A box that holds the whole surface. */
    public abstract BoundingBox boundingBox();

    /** How many primitive shapes this surface is made of (1 for a single shape). */
    public int primitiveCount() {
        return 1;
    }

    /** The total primitive count of several surfaces. */
    protected static int primitiveCount(Surface[] surfaces) {
        int n = 0;
        for (Surface s : surfaces) {
            n += s.primitiveCount();
        }
        return n;
    }

    /**
     * Whether the surface bounds a convex solid (a sphere, a box). Seen from outside, such a
     * surface cannot cast a shadow on itself; seen from inside it can (RenderPlan).
     */
    public boolean isConvex() {
        return false;
    }

    @Override
    public String toString() {
        return name;
    }
}
