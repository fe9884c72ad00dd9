package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * Every page of {@code docs/} that a file of the starter names, and every Markdown page a shipped
 * page links to, is in the starter: a student who follows a pointer finds its page (the release's
 * verification checks it too, {@link ReleaseVerifier#unshippedDocs}).
 */
class StarterDocsTest {
    @Test
    void everyPageTheStarterNamesShipsWithIt() throws IOException {
        Map<String, byte[]> starter = Release.build(Path.of("").toAbsolutePath()).files();
        assertEquals(List.of(), ReleaseVerifier.unshippedDocsOf(starter),
                "pages the starter names but does not have (" + starter.size() + " files read)");
    }

    @Test
    void theCheckFindsPlantedPointers() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("docs/shading.md", bytes("See [the format](scene-format.md#lights) and [numerics](numerics.md).\n"
                + "Also [the handout](../assignments/01-sphere/README.md) and [a site](https://example.org/x.md)."));
        files.put("docs/scene-format.md", bytes("# Scenes\n"));
        files.put("assignments/01-sphere/README.md", bytes("Read docs/shading.md, then docs/testing.md.\n"));
        files.put("src/main/java/raylab/math/Numerics.java", bytes("/** {@code docs/numerics.md} explains it. */\n"));
        files.put("scenes/sphere.png", new byte[] {(byte) 0x89, 'd', 'o', 'c', 's', '/', 'x', '.', 'm', 'd'});
        assertEquals(List.of(
                "assignments/01-sphere/README.md:1 names docs/testing.md, which the starter does not have",
                "docs/shading.md:1 links to docs/numerics.md, which the starter does not have",
                "src/main/java/raylab/math/Numerics.java:1 names docs/numerics.md, which the starter does not have"),
                ReleaseVerifier.unshippedDocsOf(files));
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
