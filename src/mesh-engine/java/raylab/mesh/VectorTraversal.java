package raylab.mesh;

import java.lang.reflect.InvocationTargetException;

/**
 * The packed engine's optional 4-wide traversal on the JDK's Vector API ({@code PackedVector}:
 * a node's four child boxes as the lanes of one {@code FloatVector}), instructor-only like
 * {@link PackedTriangles}. It computes every slab distance, entry and exit with the same float
 * and int operations as {@link PackedOctants}, lane by lane, so it enters the same children in the
 * same order and finds the same hit, t and count of triangle tests on every ray.
 *
 * <p>{@code jdk.incubator.vector} is an incubator module on JDK 17 and 25: a JVM resolves it
 * only when started with {@code --add-modules jdk.incubator.vector}, and then prints a warning.
 * So {@code PackedVector} is compiled apart (pom.xml, execution {@code vector-traversal}) and this
 * interface is all the rest of the engine sees of it. The scalar traversal is the default; the
 * vector one is taken with {@code -Draylab.mesh.traversal=vector} when the module is there
 * (docs/mesh-engine.md, "The Vector API traversal").
 */
interface VectorTraversal {
    /** The property value that asks for it. */
    String PROPERTY_VALUE = "vector";

    /**
     * As {@link PackedOctants#trace}: the leaf slot of the closest (or any) hit below
     * {@code ray[PackedWide.BEST]}, or −1; {@code lanes} is scratch for four ints.
     */
    int trace(int octant, PackedWide wide, int[] leaf, double[] tri, long[] stack, double[] ray, int kz,
            float onx, float ony, float onz, float ofx, float ofy, float ofz, float mx, float my, float mz,
            boolean anyHit, int[] lanes);

    /** Whether this JVM resolved {@code jdk.incubator.vector}. */
    static boolean moduleResolved() {
        return ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
    }

    /**
     * The vector traversal, or why there is none (one line): the module is not resolved, or
     * {@code PackedVector} was not compiled into this build.
     */
    static Object load() {
        if (!moduleResolved()) {
            return "the JVM was started without --add-modules jdk.incubator.vector";
        }
        try {
            String name = VectorTraversal.class.getPackageName() + ".PackedVector";
            return Class.forName(name).getDeclaredConstructor().newInstance();
        } catch (ClassNotFoundException | LinkageError e) {
            return "this build has no raylab.mesh.PackedVector (" + e + ")";
        } catch (NoSuchMethodException | InstantiationException | IllegalAccessException
                | InvocationTargetException e) {
            return "raylab.mesh.PackedVector cannot be made (" + e + ")";
        }
    }

    /**
     * The traversal the property {@code raylab.mesh.traversal} asks for: the vector one for
     * {@value #PROPERTY_VALUE}, else null (the scalar one). When it asks for the vector one and
     * it cannot be had, says why on standard error (one line) and returns null.
     */
    static VectorTraversal fromProperty() {
        if (!PROPERTY_VALUE.equals(System.getProperty("raylab.mesh.traversal"))) {
            return null;
        }
        Object v = load();
        if (v instanceof VectorTraversal t) {
            return t;
        }
        System.err.println("raylab: -Draylab.mesh.traversal=vector: " + v + "; the scalar 4-wide traversal is used");
        return null;
    }
}
