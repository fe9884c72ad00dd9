package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignments;

/** The release verification checks the starter README's Submitting section and that submit-check ships. */
class SubmitSectionTest {
    private static final String JAR = "lib/org/raylab/raylab-tools/1.0.0-x/raylab-tools-1.0.0-x.jar";

    /** A tools jar at the starter's repository path with these classes (empty class files: only names are read). */
    private static void toolsJar(Path starter, List<String> classes) throws Exception {
        Map<String, byte[]> entries = new TreeMap<>();
        classes.forEach(c -> entries.put(c.replace('.', '/') + ".class", new byte[0]));
        Files.createDirectories(starter.resolve(JAR).getParent());
        Files.write(starter.resolve(JAR), ToolsJar.jar(entries));
    }

    @Test
    void theStartersReadmeAndCommandPass(@TempDir Path starter) throws Exception {
        Path root = Path.of("").toAbsolutePath();
        String readme = StarterReadme.render(root, "assignments/STARTER-README.md", Assignments.load(root));
        Files.writeString(starter.resolve("README.md"), readme);
        toolsJar(starter, ReleaseVerifier.SUBMIT_CLASSES);
        assertEquals(List.of(), ReleaseVerifier.submitProblems(starter), "problems of the real starter README");

        Files.writeString(starter.resolve("README.md"), readme.replace("### PrairieLearn", "### Other")
                .replace("./raylab submit-check", "submit"));
        toolsJar(starter, ReleaseVerifier.SUBMIT_CLASSES.subList(1, 3));
        assertEquals(List.of("README.md's Submitting section does not name ./raylab submit-check",
                "README.md's Submitting section has no part \"### PrairieLearn\"",
                "raylab.cli.SubmitCheckCommand is not in the starter's tools jar (./raylab submit-check needs it)"),
                ReleaseVerifier.submitProblems(starter));

        Files.writeString(starter.resolve("README.md"), "# raylab\n");
        assertEquals("README.md has no \"## Submitting\" section", ReleaseVerifier.submitProblems(starter).get(0));
        Files.delete(starter.resolve(JAR));
        assertEquals(List.of("README.md has no \"## Submitting\" section",
                "the starter has no tools jar (lib/.../raylab-tools-*.jar)"), ReleaseVerifier.submitProblems(starter));
    }
}
