package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * The starter names nothing hidden (issue 36, item 4): the instructor's pom.xml lists every hidden
 * test class and {@code grader/tests} in its mutation profile; the starter's pom.xml has no such
 * profile, no file of the written starter names a hidden test class, and the release verification's
 * check ({@link ReleaseVerifier#namesHidden}) finds such a name or path when one is planted.
 */
class StarterNamesNothingHiddenTest {
    @TempDir
    Path dir;

    private static Set<String> hiddenClasses() throws IOException {
        Set<String> out = new HashSet<>();
        for (Assignment a : Assignments.load(Path.of("")).all()) {
            for (String h : a.tests().hidden()) {
                out.add(h.substring(h.lastIndexOf('/') + 1).replace(".java", ""));
            }
        }
        return out;
    }

    @Test
    void theStarterPomHasNoMutationProfileAndTheStarterNamesNoHiddenTest() throws IOException {
        String pom = Files.readString(Path.of("pom.xml"));
        assertTrue(pom.contains("<id>mutation</id>") && pom.contains("HiddenTest"), "the instructor's pom names them");
        String version = ToolsJar.build(Path.of("").toAbsolutePath()).version();
        String starterPom = Release.starterPom(pom, version);
        assertFalse(starterPom.contains("<id>mutation</id>") || starterPom.contains("HiddenTest")
                || starterPom.contains("grader/") || starterPom.contains("<id>course</id>")
                || starterPom.contains("src/tools/java</source>"), "the starter's pom:\n" + starterPom);
        assertTrue(starterPom.contains("<raylab.tools.version>" + version + "</raylab.tools.version>")
                && starterPom.contains("<artifactId>raylab-tools</artifactId>"), "the starter's pom names the tools jar");
        assertTrue(starterPom.contains("<artifactId>maven-surefire-plugin</artifactId>") && starterPom.contains("</project>"),
                "the rest of the pom stays");
        Path starter = dir.resolve("starter");
        Release.write(Path.of("").toAbsolutePath(), starter, false);
        List<String> files = Release.projectFiles(starter);
        assertEquals(starterPom, Files.readString(starter.resolve("pom.xml")));
        assertEquals(List.of(), ReleaseVerifier.namesHidden(starter, files, hiddenClasses()),
                "files of the starter that name a hidden test or grader/");
    }

    @Test
    void theVerificationFindsAPlantedName() throws IOException {
        Path starter = Files.createDirectories(dir.resolve("planted/docs"));
        Files.writeString(starter.resolve("notes.md"), "fine\nsee SphereHiddenTest for more\n");
        Files.writeString(dir.resolve("planted/pom.xml"), "<source>grader/tests</source>\n");
        Path src = Files.createDirectories(dir.resolve("planted/src/main/java/raylab"));
        Files.writeString(src.resolve("A.java"), "// finds grader/tests in the instructor's tree\n");
        List<String> found = ReleaseVerifier.namesHidden(dir.resolve("planted"),
                List.of("docs/notes.md", "pom.xml", "src/main/java/raylab/A.java"), Set.of("SphereHiddenTest"));
        assertEquals(List.of("docs/notes.md:2 names the hidden test SphereHiddenTest",
                "pom.xml:1 names the grader's folder (<source>grader/tests</source>)",
                "src/main/java/raylab/A.java:1 names the grader's folder (// finds grader/tests in the instruct...)"), found);
    }
}
