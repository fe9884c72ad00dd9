package raylab.ray;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.surface.Surface;

/**
 * What we know about the closest hit found so far along a ray.
 *
 * <p>A surface writes to the record only when it finds a hit that is in the ray's range
 * <em>and</em> closer than {@link #t}: that rule is what lets a group of surfaces find the
 * closest hit by asking each surface in turn. One record is reused for many rays
 * ({@link #reset()}), so tracing allocates no record per ray.
 */
public final class IntersectionRecord {
    /** Ray parameter of the closest hit so far; +∞ while there is none. */
    public double t = Double.POSITIVE_INFINITY;
    /** The hit point r(t). */
    public Vec3 point;
    /** Unit normal at the hit point, pointing out of the surface (not flipped toward the ray). */
    public Vec3 normal;
    /** The surface that was hit. */
    public Surface surface;
    /** That surface's material. */
    public Material material;
    /**
     * Which triangle of a packed mesh was hit (its index in the mesh's file order) when
     * {@link #surface} is a {@link raylab.surface.Mesh}; −1 otherwise.
     */
    public int primitive = -1;
    /** Ray–primitive intersection tests counted by groups and hierarchies, for statistics. */
    public long tests;

    /** Forgets the hit (not the test count) so the record can serve the next ray. */
    public void reset() {
        t = Double.POSITIVE_INFINITY;
        point = null;
        normal = null;
        surface = null;
        material = null;
        primitive = -1;
    }

    /** Whether a hit has been recorded since the last reset. */
    public boolean hasHit() {
        return surface != null;
    }

    /** Records a hit at t with the given point and unit outward normal on surface s. */
    public void set(double t, Vec3 point, Vec3 normal, Surface s) {
        this.t = t;
        this.point = point;
        this.normal = normal;
        this.surface = s;
        this.material = s.material();
        this.primitive = -1;
    }

    /** Copies another record's hit (not its test count). */
    public void copyFrom(IntersectionRecord o) {
        t = o.t;
        point = o.point;
        normal = o.normal;
        surface = o.surface;
        material = o.material;
        primitive = o.primitive;
    }

    @Override
    public String toString() {
        return hasHit()
                ? "hit t=" + t + " point=" + point + " normal=" + normal + " surface=" + surface
                : "no hit";
    }
}
