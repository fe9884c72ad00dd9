package raylab.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.Set;

/**
 * The surface types: the built-in ones ({@link #BUILT_IN}) and those registered on the class path
 * ({@link SurfaceType}, {@link ServiceLoader}), read once. A type that takes a built-in name,
 * repeats another's, or cannot be loaded stops the loader with one line that names it.
 *
 * <p>The built-in types are listed here rather than in a {@code META-INF/services} file of the
 * framework's: an instructor's tree has its own such file (its path is the same), which must not
 * have to repeat them, and a class path without it must still know spheres.
 */
public final class SurfaceTypes {
    /** The built-in surface types, in documentation order. */
    public static final List<SurfaceType> BUILT_IN = List.of(new raylab.scene.types.SphereType(),
            new raylab.scene.types.BoxType(), new raylab.scene.types.TriangleType(), new raylab.scene.types.MeshType());

    private static final Map<String, SurfaceType> BUILT_IN_BY_TYPE = byType(BUILT_IN);
    private static final Map<String, SurfaceType> EXTENSIONS = load();
    private static final Map<String, SurfaceType> ALL = all(BUILT_IN_BY_TYPE, EXTENSIONS);

    private SurfaceTypes() {
    }

    /** The built-in types by their {@code "type"}: sphere, box, triangle, mesh. */
    public static Map<String, SurfaceType> builtIn() {
        return BUILT_IN_BY_TYPE;
    }

    /** The registered extension types by their {@code "type"}, in class path order. */
    public static Map<String, SurfaceType> extensions() {
        return EXTENSIONS;
    }

    /** Every surface type by its {@code "type"}: the built-in ones, then the extensions. */
    public static Map<String, SurfaceType> all() {
        return ALL;
    }

    private static Map<String, SurfaceType> byType(List<SurfaceType> types) {
        Map<String, SurfaceType> m = new LinkedHashMap<>();
        types.forEach(t -> m.put(t.type(), t));
        return java.util.Collections.unmodifiableMap(m);
    }

    private static Map<String, SurfaceType> all(Map<String, SurfaceType> builtIn, Map<String, SurfaceType> extensions) {
        Map<String, SurfaceType> m = new LinkedHashMap<>(builtIn);
        m.putAll(extensions);
        return java.util.Collections.unmodifiableMap(m);
    }

    /**
     * One surface of a registered type from its scene-format JSON without {@code "material"}
     * (the surface of a data case), built by the scene loader with a normals material.
     *
     * @throws SceneException for an unknown type or a bad key, with the loader's message
     */
    public static raylab.surface.Surface build(com.fasterxml.jackson.databind.JsonNode surface) throws SceneException {
        com.fasterxml.jackson.databind.node.ObjectNode s = surface.deepCopy();
        s.put("material", "case material");
        String scene = "{\"image\": {\"width\": 1, \"height\": 1}, \"camera\": {\"type\": \"perspective\","
                + " \"eye\": [0, 0, 1], \"lookAt\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 40},"
                + " \"materials\": {\"case material\": {\"type\": \"normals\"}}, \"surfaces\": [" + s + "]}";
        try {
            return SceneLoader.parse(scene, java.nio.file.Path.of("data case")).surfaces.get(0);
        } catch (SceneException e) {
            // Said of the surface itself: "normal: ...", "missing required key ...".
            throw new SceneException(String.valueOf(e.getMessage())
                    .replaceFirst("^(?:data case\\S*: )?\\$\\.surfaces\\[0\\](?:\\.|: )", ""), e);
        }
    }

    /**
     * The scene schema ({@code scenes/scene.schema.json}) with every registered type's
     * {@link SurfaceType#schema()} under {@code $defs} and among the surface types; the text
     * unchanged when none is registered or all are in it already.
     */
    public static String schemaWithExtensions(String schemaText) throws java.io.IOException {
        return schemaWith(EXTENSIONS.values(), schemaText);
    }

    /**
     * The scene schema with each of {@code declared}' {@link SurfaceType#schema()} under
     * {@code $defs} (replacing an entry that differs) and, if missing, among the surface types
     * ({@code $defs/surface}: its {@code "type"} enum and an if/then case), appended in the given
     * order; the text unchanged when every entry is there as declared. The built-in types'
     * entries are declared by the types too: scenes/scene.schema.json is what this makes of the
     * schema without them (SceneSchemaTest holds it).
     */
    public static String schemaWith(java.util.Collection<SurfaceType> declared, String schemaText) throws java.io.IOException {
        if (declared.isEmpty()) {
            return schemaText;
        }
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        com.fasterxml.jackson.databind.node.ObjectNode schema = (com.fasterxml.jackson.databind.node.ObjectNode) json.readTree(schemaText);
        com.fasterxml.jackson.databind.node.ObjectNode defs = (com.fasterxml.jackson.databind.node.ObjectNode) schema.get("$defs");
        com.fasterxml.jackson.databind.node.ObjectNode surface = (com.fasterxml.jackson.databind.node.ObjectNode) defs.get("surface");
        com.fasterxml.jackson.databind.node.ArrayNode types = (com.fasterxml.jackson.databind.node.ArrayNode) surface.get("properties")
                .get("type").get("enum");
        com.fasterxml.jackson.databind.node.ArrayNode cases = (com.fasterxml.jackson.databind.node.ArrayNode) surface.get("allOf");
        boolean changed = false;
        for (SurfaceType t : declared) {
            if (!t.schema().equals(defs.get(t.type()))) {
                defs.set(t.type(), t.schema());
                changed = true;
            }
            boolean listed = false;
            for (com.fasterxml.jackson.databind.JsonNode v : types) {
                listed |= v.asText().equals(t.type());
            }
            if (!listed) {
                types.add(t.type());
                com.fasterxml.jackson.databind.node.ObjectNode c = cases.addObject();
                com.fasterxml.jackson.databind.node.ObjectNode cond = c.putObject("if");
                cond.putObject("properties").putObject("type").put("const", t.type());
                cond.putArray("required").add("type");
                c.putObject("then").put("$ref", "#/$defs/" + t.type());
                changed = true;
            }
        }
        if (!changed) {
            return schemaText;
        }
        List<String> all = new ArrayList<>();
        types.forEach(v -> all.add(v.asText()));
        String last = all.remove(all.size() - 1);
        surface.put("description", "Surface: " + (all.isEmpty() ? "" : String.join(", ", all) + " or ") + last + ".");
        all.add(last);
        ((com.fasterxml.jackson.databind.node.ObjectNode) surface.get("properties").get("type"))
                .put("description", "The surface type: one of " + String.join(", ", all) + ".");
        return json.writerWithDefaultPrettyPrinter().writeValueAsString(schema) + "\n";
    }

    private static Map<String, SurfaceType> load() {
        Map<String, SurfaceType> out = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        try {
            for (SurfaceType t : ServiceLoader.load(SurfaceType.class, SurfaceType.class.getClassLoader())) {
                String type = t.type();
                if (type == null || !type.matches("[a-z][A-Za-z0-9]*")) {
                    problems.add(t.getClass().getName() + ": type " + type + " is not a lowercase word");
                } else if (BUILT_IN_BY_TYPE.containsKey(type) || out.containsKey(type)) {
                    problems.add(t.getClass().getName() + ": type \"" + type + "\" is taken by "
                            + (BUILT_IN_BY_TYPE.containsKey(type) ? "a built-in surface" : out.get(type).getClass().getName()));
                } else if (!t.keys().containsAll(Set.of("type", "name", "material"))
                        || !t.keys().containsAll(t.requiredKeys()) || !t.requiredKeys().containsAll(Set.of("type", "material"))) {
                    problems.add(t.getClass().getName() + ": keys() must hold type, name, material and every required key,"
                            + " and requiredKeys() type and material");
                } else {
                    out.put(type, t);
                }
            }
        } catch (ServiceConfigurationError e) {
            problems.add(String.valueOf(e.getMessage()));
        }
        if (!problems.isEmpty()) {
            throw new IllegalStateException("surface types (META-INF/services/" + SurfaceType.class.getName() + "): "
                    + String.join("; ", problems));
        }
        return java.util.Collections.unmodifiableMap(out);
    }
}
