package raylab.scene;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import com.code_intelligence.jazzer.junit.FuzzTest;

import raylab.fuzzing.OneLine;

/**
 * Fuzzes the scene loader with arbitrary bytes as a scene file. The property: it either returns a
 * scene within the documented limits or throws a {@link SceneException} whose message is one line
 * starting with the file name, with control characters escaped; never another exception.
 *
 * <p>In {@code ./mvnw verify} (regression mode) it runs over the saved inputs in
 * src/test/resources/raylab/scene/SceneLoaderFuzzTestInputs/sceneFile; to fuzz, see the README
 * (development). Mesh references resolve next to the pretend file, where a valid and a broken OBJ
 * file lie.
 */
class SceneLoaderFuzzTest {
    static Path dir;

    @BeforeAll
    static void meshes() throws IOException {
        dir = Files.createTempDirectory("raylab-scene-fuzz");
        Files.writeString(dir.resolve("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", StandardCharsets.US_ASCII);
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 0\nf 1 2 3\n", StandardCharsets.US_ASCII);
    }

    @AfterAll
    static void cleanUp() throws IOException {
        for (String f : new String[] {"tri.obj", "bad.obj"}) {
            Files.deleteIfExists(dir.resolve(f));
        }
        Files.deleteIfExists(dir);
    }

    @FuzzTest(maxDuration = "60s")
    void sceneFile(byte[] data) {
        Path file = dir.resolve("fuzz.json");
        try {
            Scene s = SceneLoader.fromBytes(data, file);
            if (s.width < 1 || s.width > SceneLoader.MAX_IMAGE_SIZE || s.height < 1
                    || s.height > SceneLoader.MAX_IMAGE_SIZE || s.camera == null
                    || !s.camera.u.isFinite() || !s.camera.v.isFinite() || !s.camera.w.isFinite()) {
                throw new AssertionError("accepted a scene outside the limits: " + s.width + "x" + s.height);
            }
        } catch (SceneException e) {
            OneLine.check(e.getMessage(), file.toString(), true, e);
        }
    }
}
