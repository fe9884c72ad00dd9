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
 * path ({@code src/main/resources/} in the instructor's tree). The built-in types (sphere, box,
 * triangle, mesh) keep their names; an extension may not take one.
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
     * and {@link #requiredKeys()}; override it to describe and type each key.
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

    /** A surface's keys as the loader reads them, with its messages ({@code file:line:col}). */
    interface Fields {
        boolean has(String key);

        /** {@code [x, y, z]}. */
        Vec3 vec3(String key) throws SceneException;

        /** A finite number. */
        double number(String key) throws SceneException;

        /** A finite number > 0. */
        double positive(String key) throws SceneException;

        /** An error at the key's value: "scene.json:4:20: {@code message}". */
        SceneException fail(String key, String message);
    }
}
