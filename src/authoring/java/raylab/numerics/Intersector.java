package raylab.numerics;

import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * One way of intersecting a ray with one fixed shape, with the contract of
 * {@link raylab.surface.Surface#intersect}: update the record only with a hit whose t is in the
 * ray's range and closer than the record's t, and say whether it did; otherwise leave the record
 * untouched. Lets tests and the timing study swap the reference method for a simpler one.
 */
@FunctionalInterface
public interface Intersector {
    boolean intersect(IntersectionRecord rec, Ray ray);
}
