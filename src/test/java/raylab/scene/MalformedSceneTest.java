package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * The malformed-scene corpus: every file in src/test/resources/malformed/*.json must fail to load
 * with exactly the one-line message recorded in expected.tsv.
 */
class MalformedSceneTest {
    static final Path DIR = Path.of("src", "test", "resources", "malformed");
    static final int MINIMUM_CASES = 30;

    /** expected.tsv: file name TAB message (paths in the message relative to DIR). */
    static Map<String, String> expected() throws IOException {
        Map<String, String> out = new LinkedHashMap<>();
        List<String> lines = Files.readAllLines(DIR.resolve("expected.tsv"), StandardCharsets.UTF_8);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            int tab = line.indexOf('\t');
            if (tab < 0) {
                fail("expected.tsv:" + (i + 1) + ": no TAB between file name and message: " + line);
            }
            String name = line.substring(0, tab);
            if (out.put(name, line.substring(tab + 1)) != null) {
                fail("expected.tsv:" + (i + 1) + ": " + name + " is listed twice");
            }
        }
        return out;
    }

    static Set<String> jsonFiles() throws IOException {
        try (Stream<Path> s = Files.list(DIR)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".json"))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
    }

    @TestFactory
    Stream<DynamicTest> everyMalformedSceneFailsWithItsExactMessage() throws IOException {
        return expected().entrySet().stream().map(e -> DynamicTest.dynamicTest(e.getKey(), () -> {
            Path file = DIR.resolve(e.getKey());
            SceneException ex = assertThrows(SceneException.class, () -> SceneLoader.load(file),
                    () -> file + " loaded, but should fail with: " + e.getValue());
            String message = ex.getMessage();
            assertFalse(message.contains("\n") || message.contains("\r"),
                    () -> file + ": message is not one line: " + message);
            assertTrue(message.startsWith(file.toString()),
                    () -> file + ": message does not start with the file as given: " + message);
            String relative = message.replace(DIR + File.separator, "");
            assertEquals(e.getValue(), relative, () -> "message for " + file);
        }));
    }

    @Test
    void everyCorpusFileHasAnExpectedMessageAndViceVersa() throws IOException {
        Set<String> files = jsonFiles();
        Set<String> listed = new TreeSet<>(expected().keySet());
        Set<String> unlisted = new TreeSet<>(files);
        unlisted.removeAll(listed);
        Set<String> missing = new TreeSet<>(listed);
        missing.removeAll(files);
        assertTrue(unlisted.isEmpty(), () -> "corpus files without a line in expected.tsv: " + unlisted);
        assertTrue(missing.isEmpty(), () -> "expected.tsv lines without a corpus file: " + missing);
        assertTrue(files.size() >= MINIMUM_CASES,
                () -> "the corpus must have at least " + MINIMUM_CASES + " cases, has " + files.size());
    }

    @Test
    void noJacksonTextLeaksIntoMessages() throws IOException {
        for (String msg : expected().values()) {
            for (String leak : List.of("Jackson", "JsonReadFeature", "Source:", "REDACTED", "code ",
                    "token '", "Exception")) {
                assertFalse(msg.contains(leak), () -> "message contains '" + leak + "': " + msg);
            }
        }
    }
}
