package raylab.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A triangle mesh, such as one loaded from an OBJ file: its triangles share one material and are
 * traced through their own bounding volume hierarchy.
 *
 * <p>Storage is packed: the vertices of all triangles in one {@code double[]} (nine numbers per
 * triangle, in the tree's leaf order) and the tree in one {@code int[]} ({@link BvhNodes}), no
 * object per triangle or node. The leaf test is one of two kernels:
 * <ul>
 * <li>the student kernel: {@link Triangle} objects made once per mesh, in leaf order, each asked
 * its own {@code intersect} through the tree. A bug in a student's {@code Triangle.intersect}
 * therefore shows in every mesh. This is the only kernel the starter has.</li>
 * <li>the packed engine, {@code raylab.mesh.PackedTriangles}: instructor-only (the mesh engine
 * module, {@code src/mesh-engine}, which the starter does not have) with its own traversal and
 * the reference {@code Triangle.intersect} rewritten on the packed arrays, same hits, same t, bit
 * for bit. It
 * is used only where this build provides it ({@link PackedEngine}, a service) and the class
 * {@code Triangle} comes from the same code source (class folder or jar) as its provider and
 * {@code Mesh}: the instructor's own build. A student's
 * {@code Triangle} compiled anywhere else (the starter, or an overlay over the reference classes
 * in the grader) selects the student kernel, and no field or method the student writes changes
 * that.</li>
 * </ul>
 */
public final class Mesh extends Surface {
    /**
     * The packed engine of one mesh: closest hit or any hit, with {@code IntersectionRecord}
     * filled as {@link Triangle#intersect} fills it (an any hit names the blocker only). Made by
     * this build's {@link PackedEngine}.
     */
    public interface Engine {
        /**
         * The closest hit of the ray below {@code rec.t} (or, with {@code anyHit}, any hit in the
         * ray's range) written to {@code rec}, as {@link Triangle#intersect} writes it; whether
         * there is one. Adds the triangle tests to {@code rec.tests}.
         */
        boolean intersect(IntersectionRecord rec, Ray ray, boolean anyHit);

        /** Bytes of the engine's own arrays (beyond the mesh's vertices and tree). */
        long bytes();

        /** Which traversal the engine takes, in a few words (for the bench's report). */
        String traversal();
    }

    /**
     * This build's packed engine ({@link PackedEngine}, a service: the instructor's build has one,
     * the starter none), or null: when there is none, or when {@code Triangle}, {@code Mesh} and
     * its provider do not all come from one code source and class loader.
     */
    private static final PackedEngine ENGINE = findEngine();

    /** Whether meshes of this build's own {@link Triangle} objects use the packed engine. */
    public static final boolean PACKED_ENGINE = ENGINE != null;

    private final int n;
    /** Triangle at leaf slot s: a, b, c at tri[9 s .. 9 s + 9); degenerate ones collapsed to a. */
    private final double[] tri;
    private final BvhNodes tree;
    private final BoundingBox box;
    /** The triangle objects in leaf order when the student kernel is used, else null. */
    private final Triangle[] objects;
    /** The packed engine, when the student kernel is not used, else null. */
    private final Engine engine;
    private final Material material;
    /** File order → triangles, given or made on first request. */
    private volatile List<Triangle> fileOrder;
    /** Original vertices of degenerate triangles (zero normal), by file index. */
    private final Map<Integer, double[]> degenerate = new HashMap<>();

    /** A mesh of the given triangles (file order), which share the first one's material. */
    public Mesh(List<Triangle> triangles, String name) {
        this(vertices(triangles), triangles.isEmpty() ? null : triangles.get(0).material(), name,
                List.copyOf(triangles));
    }

    /**
     * A mesh of {@code vertices.length / 9} triangles given as a, b, c (nine numbers each, file
     * order), all with the given material. Triangle i is named "NAME triangle #i".
     */
    public Mesh(double[] vertices, Material material, String name) {
        this(vertices, material, name, null);
    }

    private Mesh(double[] vertices, Material material, String name, List<Triangle> given) {
        super(material, name);
        this.material = material;
        if (vertices.length % 9 != 0) {
            throw new IllegalArgumentException("nine numbers per triangle expected, got " + vertices.length);
        }
        n = vertices.length / 9;
        double[] boxes = new double[6 * n];
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = 0; i < n; i++) {
            int v = 9 * i;
            for (int k = 0; k < 3; k++) {
                // As Triangle.boundingBox(): a.min(b).min(c), a.max(b).max(c).
                double lo = Math.min(Math.min(vertices[v + k], vertices[v + 3 + k]), vertices[v + 6 + k]);
                double hi = Math.max(Math.max(vertices[v + k], vertices[v + 3 + k]), vertices[v + 6 + k]);
                boxes[6 * i + k] = lo;
                boxes[6 * i + 3 + k] = hi;
            }
            x0 = Math.min(x0, boxes[6 * i]);
            y0 = Math.min(y0, boxes[6 * i + 1]);
            z0 = Math.min(z0, boxes[6 * i + 2]);
            x1 = Math.max(x1, boxes[6 * i + 3]);
            y1 = Math.max(y1, boxes[6 * i + 4]);
            z1 = Math.max(z1, boxes[6 * i + 5]);
        }
        tree = BvhBuilder.build(boxes, n);
        boxes = null;
        tri = new double[9 * n];
        for (int s = 0; s < n; s++) {
            int f = tree.order[s];
            System.arraycopy(vertices, 9 * f, tri, 9 * s, 9);
            if (isDegenerate(tri, 9 * s)) {
                degenerate.put(f, java.util.Arrays.copyOfRange(vertices, 9 * f, 9 * f + 9));
                // All three vertices equal: every edge function is exactly 0, so det = 0 and the
                // kernel reports no hit, as Triangle.intersect does for a zero normal.
                System.arraycopy(tri, 9 * s, tri, 9 * s + 3, 3);
                System.arraycopy(tri, 9 * s, tri, 9 * s + 6, 3);
            }
        }
        box = n == 0 ? BoundingBox.EMPTY : new BoundingBox(new Vec3(x0, y0, z0), new Vec3(x1, y1, z1));
        fileOrder = given;
        boolean student = ENGINE == null;
        if (given != null) {
            for (Triangle t : given) {
                student |= t.getClass() != Triangle.class;
            }
        }
        if (student) {
            List<Triangle> all = triangles();
            objects = new Triangle[n];
            for (int s = 0; s < n; s++) {
                objects[s] = all.get(tree.order[s]);
            }
            engine = null;
        } else {
            objects = null;
            engine = newEngine(tri, tree, material);
        }
    }

    private Engine newEngine(double[] tri, BvhNodes tree, Material material) {
        return ENGINE.of(this, tri, tree, material);
    }

    private static PackedEngine findEngine() {
        if (!sameOrigin(Triangle.class, Mesh.class)) {
            return null;
        }
        java.util.Iterator<PackedEngine> it = java.util.ServiceLoader.load(PackedEngine.class, Mesh.class.getClassLoader())
                .iterator();
        while (true) {
            try {
                if (!it.hasNext()) {
                    return null; // the starter: no packed engine
                }
                PackedEngine e = it.next();
                if (sameOrigin(e.getClass(), Mesh.class)) {
                    return e;
                }
            } catch (java.util.ServiceConfigurationError | LinkageError e) {
                // a listed provider this build lacks or cannot make: not an engine
            }
        }
    }

    /** Same class loader and same code source location (the same class folder or jar). */
    static boolean sameOrigin(Class<?> a, Class<?> b) {
        if (a.getClassLoader() != b.getClassLoader()) {
            return false;
        }
        java.security.CodeSource ca = a.getProtectionDomain().getCodeSource();
        java.security.CodeSource cb = b.getProtectionDomain().getCodeSource();
        return ca != null && cb != null && ca.getLocation() != null && ca.getLocation().equals(cb.getLocation());
    }

    private static double[] vertices(List<Triangle> triangles) {
        double[] v = new double[9 * triangles.size()];
        int k = 0;
        for (Triangle t : triangles) {
            for (Vec3 p : new Vec3[] {t.a, t.b, t.c}) {
                v[k++] = p.x;
                v[k++] = p.y;
                v[k++] = p.z;
            }
        }
        return v;
    }

    /** Whether (b − a) × (c − a) is the zero vector, computed as Triangle.intersect does. */
    private static boolean isDegenerate(double[] t, int o) {
        double ux = t[o + 3] - t[o], uy = t[o + 4] - t[o + 1], uz = t[o + 5] - t[o + 2];
        double vx = t[o + 6] - t[o], vy = t[o + 7] - t[o + 1], vz = t[o + 8] - t[o + 2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        return nx == 0 && ny == 0 && nz == 0;
    }

    /** The packed engine that traces this mesh, or null with the student kernel (for the engine's tests). */
    public Engine packedEngine() {
        return engine;
    }

    /** Whether rays are tested by the packed engine (else by the Triangle objects). */
    public boolean usesPackedKernel() {
        return engine != null;
    }

    /** The kernel and traversal that test rays, in a few words (for the bench's report). */
    public String kernel() {
        return engine == null ? "Triangle.intersect kernel" : "packed kernel, " + engine.traversal();
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        if (objects != null) {
            return tree.traverse(outRecord, ray, objects, false);
        }
        return engine.intersect(outRecord, ray, false);
    }

    @Override
    public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
        scratch.reset();
        if (objects != null) {
            return tree.traverse(scratch, ray, objects, true);
        }
        return engine.intersect(scratch, ray, true);
    }

    @Override
    public BoundingBox boundingBox() {
        return box;
    }

    @Override
    public int primitiveCount() {
        return n;
    }

    /** Number of nodes of the mesh's tree. */
    public int nodeCount() {
        return tree.count;
    }

    /** Depth of the mesh's tree (1 for a single leaf). */
    public int depth() {
        return tree.depth;
    }

    /** Bytes held by the packed triangles and the tree (not counting Triangle objects). */
    public long packedBytes() {
        return 8L * tri.length + 4L * tree.inner.length + 4L * tree.leaf.length + 4L * tree.order.length
                + (engine == null ? 0 : engine.bytes());
    }

    /** The triangles, in file order (made on first request when the mesh was built from arrays). */
    public List<Triangle> triangles() {
        List<Triangle> list = fileOrder;
        if (list == null) {
            Triangle[] all = new Triangle[n];
            for (int s = 0; s < n; s++) {
                int f = tree.order[s];
                double[] v = degenerate.get(f);
                int o = 0;
                if (v == null) {
                    v = tri;
                    o = 9 * s;
                }
                all[f] = new Triangle(new Vec3(v[o], v[o + 1], v[o + 2]), new Vec3(v[o + 3], v[o + 4], v[o + 5]),
                        new Vec3(v[o + 6], v[o + 7], v[o + 8]), material, name() + " triangle #" + f);
            }
            list = Collections.unmodifiableList(new ArrayList<>(List.of(all)));
            fileOrder = list;
        }
        return list;
    }
}
