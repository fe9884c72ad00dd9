package raylab.surface;

import java.util.List;

import raylab.math.BoundingBox;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * Many surfaces tested one after another: the closest hit over all of them.
 *
 * <p>Because each surface only writes a hit closer than the record's current t, asking every
 * member in turn leaves the closest hit in the record. The cost is linear in the member count;
 * {@link Bvh} does the same job in about logarithmic time.
 */
public final class Group extends Surface {
    private final Surface[] members;
    private final BoundingBox box;

    public Group(List<? extends Surface> members, String name) {
        super(null, name);
        this.members = members.toArray(new Surface[0]);
        BoundingBox b = BoundingBox.EMPTY;
        for (Surface s : this.members) {
            b = b.union(s.boundingBox());
        }
        this.box = b;
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        boolean hit = false;
        for (Surface s : members) {
            outRecord.tests++;
            if (s.intersect(outRecord, ray)) {
                hit = true;
            }
        }
        return hit;
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        for (Surface s : members) {
            scratch.tests++;
            if (s.intersectsAny(ray, scratch)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public BoundingBox boundingBox() {
        return box;
    }

    @Override
    public int primitiveCount() {
        return Surface.primitiveCount(members);
    }

    @Override
    public boolean isConvex() {
        return members.length == 1 && members[0].isConvex();
    }

    /** The members, in order. */
    public List<Surface> members() {
        return List.of(members);
    }
}
