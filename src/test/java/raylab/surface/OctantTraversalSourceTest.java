package raylab.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;

import org.junit.jupiter.api.Test;

/** The committed octant and vector traversals are the generator's output (regenerate: see OctantTraversalSource). */
class OctantTraversalSourceTest {
    @Test
    void packedOctantsIsWhatTheGeneratorMakes() throws IOException {
        String committed = Files.readString(OctantTraversalSource.FILE, StandardCharsets.UTF_8);
        String generated = OctantTraversalSource.source();
        assertEquals(generated, committed, OctantTraversalSource.FILE
                + " differs from the generator's output: run java src/test/java/raylab/surface/OctantTraversalSource.java");
    }

    @Test
    void packedVectorIsWhatTheGeneratorMakes() throws IOException {
        String committed = Files.readString(OctantTraversalSource.VECTOR_FILE, StandardCharsets.UTF_8);
        assertEquals(OctantTraversalSource.vectorSource(), committed, OctantTraversalSource.VECTOR_FILE
                + " differs from the generator's output: run java src/test/java/raylab/surface/OctantTraversalSource.java");
    }
}
