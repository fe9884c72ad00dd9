package raylab.scene.types;

import java.io.UncheckedIOException;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.scene.SurfaceType;

/**
 * A built-in type's entry in the scene schema ({@link SurfaceType#schema()}): what every surface
 * has ("type", "name", "material", closed, its required keys) and its own keys, written as JSON.
 */
final class SchemaJson {
    /** A point or vector {@code [x, y, z]}: the schema of such a key, besides its description. */
    static final String POINT = "\"type\": \"array\", \"items\": {\"type\": \"number\"}, \"minItems\": 3, \"maxItems\": 3";

    private static final ObjectMapper JSON = new ObjectMapper();

    private SchemaJson() {
    }

    /**
     * The entry of {@code t}: {@code description}, its {@code "type"} described as
     * {@code typeDescription}, "name" and "material", the keys {@code properties} (a JSON object of
     * the type's own keys) and {@code t.requiredKeys()} as required.
     */
    static ObjectNode entry(SurfaceType t, String description, String typeDescription, String properties) {
        ObjectNode s = JSON.createObjectNode();
        s.put("description", description);
        s.put("type", "object");
        s.put("additionalProperties", false);
        ObjectNode p = s.putObject("properties");
        p.putObject("type").put("description", typeDescription).put("const", t.type());
        p.putObject("name").put("description", "A name for messages and statistics. Default: \"" + t.type() + " #<index>\".")
                .put("type", "string").put("minLength", 1);
        p.putObject("material").put("description", "The name of a material defined under \"materials\".").put("type", "string");
        try {
            p.setAll((ObjectNode) JSON.readTree(properties));
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(t.type() + ": the schema's properties are not JSON: " + e.getOriginalMessage(), e);
        }
        t.requiredKeys().forEach(s.putArray("required")::add);
        return s;
    }
}
