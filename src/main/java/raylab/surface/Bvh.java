package raylab.surface;

import java.util.List;

import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A bounding volume hierarchy: the same closest hit as {@link Group}, found by skipping every
 * subtree whose bounding box the ray misses or reaches only beyond the closest hit so far.
 *
 * <p>Built top-down with the surface area heuristic over 12 bins per axis ({@link BvhBuilder});
 * nodes are stored in one flat array ({@link BvhNodes}), and traversal visits the nearer child
 * first and allocates nothing. Building is deterministic, so the same scene always gives the same
 * tree (and the same image). Triangle meshes use the same tree over packed triangles instead
 * ({@link Mesh}).
 */
public final class Bvh extends Surface {
    private final Surface[] prims;
    private final BvhNodes tree;
    private final BoundingBox box;

    public Bvh(List<? extends Surface> surfaces, String name) {
        super(null, name);
        Surface[] given = surfaces.toArray(new Surface[0]);
        int n = given.length;
        double[] boxes = new double[6 * n];
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = 0; i < n; i++) {
            BoundingBox b = given[i].boundingBox();
            boxes[6 * i] = b.min.x;
            boxes[6 * i + 1] = b.min.y;
            boxes[6 * i + 2] = b.min.z;
            boxes[6 * i + 3] = b.max.x;
            boxes[6 * i + 4] = b.max.y;
            boxes[6 * i + 5] = b.max.z;
            x0 = Math.min(x0, b.min.x);
            y0 = Math.min(y0, b.min.y);
            z0 = Math.min(z0, b.min.z);
            x1 = Math.max(x1, b.max.x);
            y1 = Math.max(y1, b.max.y);
            z1 = Math.max(z1, b.max.z);
        }
        tree = BvhBuilder.build(boxes, n);
        prims = new Surface[n];
        for (int i = 0; i < n; i++) {
            prims[i] = given[tree.order[i]];
        }
        box = n == 0 ? BoundingBox.EMPTY : new BoundingBox(new Vec3(x0, y0, z0), new Vec3(x1, y1, z1));
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        return tree.traverse(outRecord, ray, prims, false);
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        scratch.reset();
        return tree.traverse(scratch, ray, prims, true);
    }

    @Override
    public BoundingBox boundingBox() {
        return box;
    }

    @Override
    public int primitiveCount() {
        return Surface.primitiveCount(prims);
    }

    /** Number of nodes in the tree. */
    public int nodeCount() {
        return tree.count;
    }

    /** Depth of the tree (1 for a single leaf). */
    public int depth() {
        return tree.depth;
    }
}
