package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.camera.PerspectiveCamera;
import raylab.surface.Mesh;

/** The complete example in docs/scene-format.md loads (with a small OBJ beside it). */
class SceneFormatDocTest {
    @Test
    void theDocumentedExampleLoads(@TempDir Path tmp) throws Exception {
        String doc = Files.readString(Path.of("docs", "scene-format.md"));
        int start = doc.indexOf("```json\n");
        assertTrue(start >= 0, "docs/scene-format.md has no ```json block");
        int end = doc.indexOf("```", start + 8);
        String example = doc.substring(start + 8, end);

        Files.createDirectories(tmp.resolve("meshes"));
        Files.writeString(tmp.resolve("meshes/tetra.obj"),
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        Path file = tmp.resolve("example.json");
        Files.writeString(file, example);

        Scene s = SceneLoader.load(file);
        assertEquals(320, s.width);
        assertEquals(240, s.height);
        assertInstanceOf(PerspectiveCamera.class, s.camera);
        assertEquals(4, s.surfaces.size());
        assertEquals(4, assertInstanceOf(Mesh.class, s.surfaces.get(3)).primitiveCount());
        assertEquals(2, s.lights.size());
        assertEquals(4, s.materials().size());
    }
}
