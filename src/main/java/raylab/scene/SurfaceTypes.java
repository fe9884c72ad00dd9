package raylab.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.Set;

/**
 * The surface types registered on the class path ({@link SurfaceType}, {@link ServiceLoader}),
 * read once. A type that takes a built-in name, repeats another's, or cannot be loaded stops the
 * loader with one line that names it.
 */
public final class SurfaceTypes {
    /** The built-in surface types, in documentation order. */
    public static final List<String> BUILT_IN = List.of("sphere", "box", "triangle", "mesh");

    private static final Map<String, SurfaceType> EXTENSIONS = load();

    private SurfaceTypes() {
    }

    /** The registered extension types by their {@code "type"}, in class path order. */
    public static Map<String, SurfaceType> extensions() {
        return EXTENSIONS;
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

    private static Map<String, SurfaceType> load() {
        Map<String, SurfaceType> out = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        try {
            for (SurfaceType t : ServiceLoader.load(SurfaceType.class, SurfaceType.class.getClassLoader())) {
                String type = t.type();
                if (type == null || !type.matches("[a-z][A-Za-z0-9]*")) {
                    problems.add(t.getClass().getName() + ": type " + type + " is not a lowercase word");
                } else if (BUILT_IN.contains(type) || out.containsKey(type)) {
                    problems.add(t.getClass().getName() + ": type \"" + type + "\" is taken by "
                            + (BUILT_IN.contains(type) ? "a built-in surface" : out.get(type).getClass().getName()));
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
