package raylab.scene;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import com.code_intelligence.jazzer.junit.FuzzTest;

import raylab.math.Vec3;
import raylab.fuzzing.OneLine;

/**
 * Fuzzes the OBJ reader through its public API with arbitrary bytes as an OBJ file. The property:
 * it returns at least one triangle with finite vertices, or throws an {@link
 * ObjLoader.ObjException} whose message is one line starting with the name it was given; never
 * another exception. Saved inputs: src/test/resources/raylab/scene/ObjLoaderFuzzTestInputs/objFile.
 */
class ObjLoaderFuzzTest {
    static Path dir;

    @BeforeAll
    static void folder() throws IOException {
        dir = Files.createTempDirectory("raylab-obj-fuzz");
    }

    @AfterAll
    static void cleanUp() throws IOException {
        Files.deleteIfExists(dir.resolve("fuzz.obj"));
        Files.deleteIfExists(dir);
    }

    @FuzzTest(maxDuration = "60s")
    void objFile(byte[] data) throws IOException {
        Path file = dir.resolve("fuzz.obj");
        Files.write(file, data);
        try {
            List<Vec3[]> triangles = ObjLoader.readTriangles(file, "fuzz.obj");
            if (triangles.isEmpty()) {
                throw new AssertionError("no triangles, but no error either");
            }
            for (Vec3[] t : triangles) {
                if (t.length != 3 || !t[0].isFinite() || !t[1].isFinite() || !t[2].isFinite()) {
                    throw new AssertionError("a triangle that is not three finite vertices");
                }
            }
        } catch (ObjLoader.ObjException e) {
            OneLine.check(e.getMessage(), "fuzz.obj", false, e);
        }
    }
}
