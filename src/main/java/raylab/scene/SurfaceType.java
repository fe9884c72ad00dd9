package raylab.scene;

import java.util.List;

import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.material.Material;
import raylab.math.Vec3;
import raylab.surface.Surface;

/**
 * A surface type an instructor adds to the scene format without editing the framework (a plane,
 * a disc, a cylinder): its {@code "type"} entry, how it is built from a scene, and how a graded
 * scene's variant moves it. Registered with {@link java.util.ServiceLoader}: a line with the
 * implementing class's name in {@code META-INF/services/raylab.scene.SurfaceType} on the class
 * path ({@code src/main/resources/} in the instructor's tree). The built-in types are
 * implementations of this interface as well ({@link raylab.scene.types.SphereType},
 * {@link raylab.scene.types.BoxType}, {@link raylab.scene.types.TriangleType},
 * {@link raylab.scene.types.MeshType}), listed in {@link SurfaceTypes#BUILT_IN}; they keep their
 * names and an extension may not take one.
 *
 * <p>The surface class itself follows the process boundary's rule (the autograder's documentation,
 * "Protocol"): a public constructor, and a public field or accessor named like each of its
 * parameters, from which the grader rebuilds the student's object.
 */
public interface SurfaceType {
    /** The JSON {@code "type"}, lowercase: {@code "plane"}. */
    String type();

    /** How messages name one: {@code "a plane"}. */
    String description();

    /**
     * The keys a surface of this type may have, in documentation order, {@code "type"},
     * {@code "name"} and {@code "material"} included.
     */
    List<String> keys();

    /** The keys it must have ({@code "type"} and {@code "material"} included). */
    List<String> requiredKeys();

    /**
     * Builds the surface from its checked keys (unknown and missing keys were refused already).
     *
     * @throws SceneException from {@link Fields#fail} for a value out of range
     */
    Surface build(Fields fields, Material material, String name) throws SceneException;

    /**
     * Moves the surface's JSON by {@code d} (a graded scene's variant, {@code "placement"}):
     * every point of it, so that it keeps its shape.
     */
    void move(ObjectNode surface, double[] d);

    /**
     * Its entry under {@code $defs} of {@code scenes/scene.schema.json} (JSON Schema 2020-12),
     * which {@code raylab release} merges into the starter's schema and the instructor's. The
     * default: an object with exactly {@link #keys()} (any value, {@code "type"} this type's)
     * and {@link #requiredKeys()}; override it to describe and type each key, as the built-in
     * types do (their entries in the framework's schema file are theirs: SceneSchemaTest).
     */
    default ObjectNode schema() {
        ObjectNode s = new com.fasterxml.jackson.databind.ObjectMapper().createObjectNode();
        s.put("description", description().substring(0, 1).toUpperCase(java.util.Locale.ROOT)
                + description().substring(1) + ".");
        s.put("type", "object");
        s.put("additionalProperties", false);
        ObjectNode props = s.putObject("properties");
        for (String k : keys()) {
            ObjectNode p = props.putObject(k);
            if (k.equals("type")) {
                p.put("const", type());
            } else if (k.equals("name") || k.equals("material")) {
                p.put("type", "string");
            }
        }
        requiredKeys().forEach(s.putArray("required")::add);
        return s;
    }

    /**
     * What {@code raylab trace} adds to its line about a surface the eye ray missed or touched:
     * "; the ray is parallel to the plane (n·d = 0)", or "" (the default). Called for every
     * surface: answer "" for one that is not of this type.
     */
    default String traceNote(Surface s, raylab.ray.Ray ray) {
        return "";
    }

    /**
     * What {@code raylab trace} says is wrong with a hit on a surface of this type beyond the
     * rules every surface keeps ("a sphere's normal points out of the sphere, ..."), or null (the
     * default). Called for every surface: answer null for one that is not of this type.
     */
    default String traceRule(Surface s, Vec3 point, Vec3 normal) {
        return null;
    }

    /**
     * For the render plan's shadow-ray rule (raylab.render.RenderPlan.seenFromOutsideOnly):
     * whether {@code eye} lies outside a surface of this type that is a convex solid, by more
     * than {@code margin} of its size; null when {@code s} is not of this type or the type cannot
     * say (the default), and the plan traces every shadow ray.
     */
    default Boolean eyeOutsideConvex(Surface s, Vec3 eye, double margin) {
        return null;
    }

    /**
     * The primitives a surface of this type is made of, each traced on its own by the plan's
     * brute force and by {@code raylab trace} (a mesh's triangles), or null when {@code s} is not
     * of this type or is one primitive (the default).
     */
    default List<Surface> primitives(Surface s) {
        return null;
    }

    /**
     * Whether a data case (the grader's README, "Data cases") may have a surface of this type: true
     * unless overridden (a mesh may not).
     */
    default boolean inDataCases() {
        return true;
    }

    /**
     * The problem with a data case's {@code "surface"} of this type, said without the case's
     * position ({@code "\"surface\": normal: expected an array [...], got a string"}), or null
     * for none. The default: its scene-format keys, checked by the scene loader.
     */
    default String caseProblem(com.fasterxml.jackson.databind.JsonNode surface) {
        try {
            SurfaceTypes.build(surface);
            return null;
        } catch (SceneException e) {
            return "\"surface\": " + e.getMessage();
        }
    }

    /**
     * A data case's surface, checked by {@link #caseProblem} already, with material {@code m}
     * (the case's). The default builds it from its scene-format keys with the scene loader (and
     * a normals material).
     *
     * @throws SceneException with the loader's message for a bad key
     */
    default Surface buildCase(com.fasterxml.jackson.databind.JsonNode surface, Material m) throws SceneException {
        return SurfaceTypes.build(surface);
    }

    /** An OBJ file a key names, as read by the loader: its name as messages show it, its triangles. */
    record ObjFile(String path, double[] triangleVertices) {
    }

    /** A surface's keys as the loader reads them, with its messages ({@code file:line:col}). */
    interface Fields {
        boolean has(String key);

        /** {@code [x, y, z]}. */
        Vec3 vec3(String key) throws SceneException;

        /** A finite number. */
        double number(String key) throws SceneException;

        /** A finite number > 0. */
        double positive(String key) throws SceneException;

        /** A string. */
        String string(String key) throws SceneException;

        /** The length of an array. */
        int count(String key) throws SceneException;

        /** Item {@code index} of an array, {@code [x, y, z]}. */
        Vec3 vec3(String key, int index) throws SceneException;

        /**
         * The OBJ file the key names, relative to the scene file's directory (a regular file,
         * parsed; any problem is a message at the key's value).
         */
        ObjFile objFile(String key) throws SceneException;

        /** An error at the key's value: "scene.json:4:20: {@code message}". */
        SceneException fail(String key, String message);
    }
}
