package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignments;

/** The release verification checks the starter README's Submitting section and that submit-check ships. */
class SubmitSectionTest {
    static final List<String> SOURCES = List.of("src/main/java/raylab/cli/SubmitCheckCommand.java",
            "src/main/java/raylab/course/Submission.java", "src/main/java/raylab/course/PackageScanner.java");

    @Test
    void theStartersReadmeAndCommandPass(@TempDir Path starter) throws Exception {
        Path root = Path.of("").toAbsolutePath();
        String readme = StarterReadme.render(root, "assignments/STARTER-README.md", Assignments.load(root));
        Files.writeString(starter.resolve("README.md"), readme);
        for (String f : SOURCES) {
            Files.createDirectories(starter.resolve(f).getParent());
            Files.copy(root.resolve(f), starter.resolve(f));
        }
        assertEquals(List.of(), ReleaseVerifier.submitProblems(starter), "problems of the real starter README");

        Files.writeString(starter.resolve("README.md"), readme.replace("### PrairieLearn", "### Other")
                .replace("./raylab submit-check", "submit"));
        Files.delete(starter.resolve(SOURCES.get(0)));
        assertEquals(List.of("README.md's Submitting section does not name ./raylab submit-check",
                "README.md's Submitting section has no part \"### PrairieLearn\"",
                SOURCES.get(0) + " is not in the starter (./raylab submit-check needs it)"),
                ReleaseVerifier.submitProblems(starter));

        Files.writeString(starter.resolve("README.md"), "# raylab\n");
        assertEquals("README.md has no \"## Submitting\" section", ReleaseVerifier.submitProblems(starter).get(0));
    }
}
