package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * scenes/scene.schema.json agrees with the loader: for every kind of object the schema's
 * properties are exactly the keys the loader accepts, the required keys match, the "type" enums
 * match the loader's types, objects are closed and every property has a description.
 */
class SceneSchemaTest {
    static final Path SCHEMA = Path.of("scenes", "scene.schema.json");
    static JsonNode schema;

    @BeforeAll
    static void parseSchema() throws IOException {
        schema = new ObjectMapper().readTree(SCHEMA.toFile());
    }

    private static JsonNode definition(String kind) {
        return kind.equals("scene") ? schema : schema.path("$defs").path(kind);
    }

    private static Set<String> names(JsonNode object) {
        Set<String> out = new TreeSet<>();
        object.fieldNames().forEachRemaining(out::add);
        return out;
    }

    private static Set<String> strings(JsonNode array) {
        Set<String> out = new TreeSet<>();
        array.forEach(n -> out.add(n.asText()));
        return out;
    }

    @Test
    void schemaIsDraft202012() {
        assertEquals("https://json-schema.org/draft/2020-12/schema", schema.path("$schema").asText());
    }

    @TestFactory
    Stream<DynamicTest> schemaPropertiesEqualTheLoadersAcceptedKeys() {
        return SceneLoader.ACCEPTED_KEYS.entrySet().stream().map(e -> DynamicTest.dynamicTest(e.getKey(), () -> {
            JsonNode def = definition(e.getKey());
            assertTrue(def.isObject(), () -> "schema has no definition for " + e.getKey());
            assertEquals(new TreeSet<>(e.getValue()), names(def.path("properties")),
                    () -> "properties of " + e.getKey() + " (schema) vs accepted keys (loader)");
            assertEquals(new TreeSet<>(SceneLoader.REQUIRED_KEYS.get(e.getKey())),
                    strings(def.path("required")), () -> "required keys of " + e.getKey());
            assertFalse(def.path("additionalProperties").asBoolean(true),
                    () -> e.getKey() + " must have additionalProperties false");
        }));
    }

    @Test
    void everyClosedDefinitionIsAKindTheLoaderKnows() {
        Set<String> closed = new TreeSet<>();
        schema.path("$defs").properties().forEach(e -> {
            if (e.getValue().has("properties") && e.getValue().has("additionalProperties")) {
                closed.add(e.getKey());
            }
        });
        closed.add("scene");
        assertEquals(new TreeSet<>(SceneLoader.ACCEPTED_KEYS.keySet()), closed);
    }

    @Test
    void typeEnumsAndTheirDefinitionsMatchTheLoader() {
        Map<String, Map<String, String>> families = Map.of("surface", SceneLoader.SURFACE_TYPES,
                "material", SceneLoader.MATERIAL_TYPES, "camera", SceneLoader.CAMERA_TYPES,
                "light", SceneLoader.LIGHT_TYPES);
        families.forEach((family, types) -> {
            JsonNode dispatch = schema.path("$defs").path(family);
            assertEquals(new TreeSet<>(types.keySet()), strings(dispatch.path("properties").path("type").path("enum")),
                    family + " type enum");
            // each "if type == t then $ref kind" pair, and each kind's "type" const
            Set<String> pairs = new TreeSet<>();
            for (JsonNode branch : dispatch.path("allOf")) {
                String t = branch.path("if").path("properties").path("type").path("const").asText();
                String ref = branch.path("then").path("$ref").asText();
                pairs.add(t + "->" + ref);
            }
            Set<String> expected = new TreeSet<>();
            types.forEach((t, kind) -> {
                expected.add(t + "->#/$defs/" + kind);
                assertEquals(t, schema.path("$defs").path(kind).path("properties").path("type").path("const").asText(),
                        kind + ".type const");
            });
            assertEquals(expected, pairs, family + " dispatch");
        });
    }

    @Test
    void everyPropertyHasADescription() {
        List<String> missing = new ArrayList<>();
        collectMissingDescriptions(schema, "#", missing);
        assertTrue(missing.isEmpty(), () -> "properties without a description: " + missing);
    }

    private static void collectMissingDescriptions(JsonNode node, String where, List<String> missing) {
        if (node.isObject()) {
            JsonNode props = node.get("properties");
            if (props != null && props.isObject()) {
                props.properties().forEach(e -> {
                    if (!e.getValue().path("description").isTextual()
                            || e.getValue().path("description").asText().isBlank()) {
                        missing.add(where + "/properties/" + e.getKey());
                    }
                });
            }
            for (Map.Entry<String, JsonNode> e : node.properties()) {
                if (e.getKey().equals("if")) {
                    continue; // conditions name properties, they do not define them
                }
                collectMissingDescriptions(e.getValue(), where + "/" + e.getKey(), missing);
            }
        } else if (node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                collectMissingDescriptions(node.get(i), where + "/" + i, missing);
            }
        }
    }

    @Test
    void allInternalReferencesResolve() {
        List<String> broken = new ArrayList<>();
        collectBrokenRefs(schema, broken);
        assertTrue(broken.isEmpty(), () -> "unresolved $ref: " + broken);
    }

    private static void collectBrokenRefs(JsonNode node, List<String> broken) {
        if (node.isObject()) {
            JsonNode ref = node.get("$ref");
            if (ref != null && (!ref.asText().startsWith("#/") || schema.at(ref.asText().substring(1)).isMissingNode())) {
                broken.add(ref.asText());
            }
            node.elements().forEachRemaining(n -> collectBrokenRefs(n, broken));
        } else if (node.isArray()) {
            node.elements().forEachRemaining(n -> collectBrokenRefs(n, broken));
        }
    }

    /**
     * The built-in types' entries are declared by the types ({@link SurfaceType#schema()}):
     * each entry of the file is its type's, and merging the types into the file changes nothing.
     */
    @Test
    void builtInEntriesAreWhatTheTypesDeclare() throws IOException {
        for (SurfaceType t : SurfaceTypes.BUILT_IN) {
            assertEquals(t.schema(), definition(t.type()), () -> "$defs/" + t.type() + ": " + t.getClass().getName()
                    + ".schema() (expected) vs scenes/scene.schema.json (actual)");
        }
        String text = java.nio.file.Files.readString(SCHEMA);
        assertEquals(text, SurfaceTypes.schemaWith(SurfaceTypes.BUILT_IN, text),
                "scenes/scene.schema.json merged with the built-in types must be unchanged");
    }

    /**
     * The file's surface entries come from the types alone: with every built-in entry taken out
     * ($defs, the "type" enum, the if/then cases), merging the built-in types gives the file back.
     */
    @Test
    void builtInTypesAloneMakeTheSurfaceEntries() throws IOException {
        ObjectMapper json = new ObjectMapper();
        com.fasterxml.jackson.databind.node.ObjectNode without = schema.deepCopy();
        com.fasterxml.jackson.databind.node.ObjectNode defs = (com.fasterxml.jackson.databind.node.ObjectNode) without.get("$defs");
        com.fasterxml.jackson.databind.node.ObjectNode surface = (com.fasterxml.jackson.databind.node.ObjectNode) defs.get("surface");
        for (SurfaceType t : SurfaceTypes.BUILT_IN) {
            assertTrue(defs.remove(t.type()) != null, "scenes/scene.schema.json has no $defs/" + t.type());
        }
        ((com.fasterxml.jackson.databind.node.ArrayNode) surface.at("/properties/type/enum")).removeAll();
        ((com.fasterxml.jackson.databind.node.ArrayNode) surface.get("allOf")).removeAll();
        surface.put("description", "(rewritten)");
        JsonNode made = json.readTree(SurfaceTypes.schemaWith(SurfaceTypes.BUILT_IN, json.writeValueAsString(without)));
        assertEquals(schema, made, "scenes/scene.schema.json (expected) vs the schema without its surface entries"
                + " merged with the built-in types (actual)");
        assertEquals("[\"sphere\",\"box\",\"triangle\",\"mesh\"]", made.at("/$defs/surface/properties/type/enum").toString(),
                "surface types in order");
    }
}
