package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * docs/instructors.md names the files each milestone grades where instructors read them: the
 * table of "One milestone, its own files" and each platform's section (what students upload). Every
 * such list must be the assignments' {@code files} exactly, and no platform section may name a
 * student file of the wrong milestone (issue 36, item 10: lambert grades Lambertian.java and
 * Shading.java; shadows uploads Shadows.java).
 */
class DocsFileListsTest {
    static final Path DOC = Path.of("docs/instructors.md");

    private static Map<String, Set<String>> assignmentFiles() throws IOException {
        Map<String, Set<String>> out = new LinkedHashMap<>();
        for (Assignment a : Assignments.load(Path.of("")).all()) {
            Set<String> files = new TreeSet<>();
            a.files().forEach(f -> files.add(f.path()));
            out.put(a.id(), files);
        }
        return out;
    }

    private static Set<String> names(Set<String> paths) {
        Set<String> out = new TreeSet<>();
        paths.forEach(p -> out.add(p.substring(p.lastIndexOf('/') + 1)));
        return out;
    }

    /** The text of the section that starts with this heading line, up to the next heading of its level or above. */
    static String section(String doc, String heading) {
        int k = doc.indexOf("\n" + heading + "\n");
        assertTrue(k >= 0, "docs/instructors.md has the section " + heading);
        int level = heading.indexOf(' ');
        int end = doc.length();
        Matcher m = Pattern.compile("\n#{1," + level + "} ").matcher(doc);
        if (m.find(k + heading.length() + 1)) {
            end = m.start();
        }
        return doc.substring(k, end);
    }

    @Test
    void theTableOfEachMilestonesFilesIsTheAssignments() throws IOException {
        String doc = Files.readString(DOC);
        Map<String, Set<String>> want = assignmentFiles();
        Map<String, Set<String>> table = new LinkedHashMap<>();
        Matcher row = Pattern.compile("\n\\| (\\w+) +\\| (`[^|]+) \\|").matcher(section(doc, "## The single source"));
        while (row.find()) {
            Set<String> files = new TreeSet<>();
            Matcher f = Pattern.compile("`([^`]+\\.java)`").matcher(row.group(2));
            while (f.find()) {
                files.add(f.group(1));
            }
            table.put(row.group(1), files);
        }
        assertEquals(want, table, "the table of each milestone's files in docs/instructors.md (expected: the assignments)");
    }

    @Test
    void prairieLearnsUploadListIsTheAssignments() throws IOException {
        String pl = section(Files.readString(DOC), "### PrairieLearn");
        Map<String, Set<String>> want = new LinkedHashMap<>();
        assignmentFiles().forEach((id, files) -> want.put(id, names(files)));
        // "(sphere `Sphere.java`; ...; lambert `Lambertian.java`, `Shading.java`; ...)"
        Matcher list = Pattern.compile("\\(((?:\\w+ `[^`]+`(?:,\\s*`[^`]+`)*;?\\s*)+)\\)").matcher(pl);
        assertTrue(list.find(), "the PrairieLearn section lists each milestone's upload: " + pl);
        Map<String, Set<String>> got = new LinkedHashMap<>();
        for (String part : list.group(1).split(";")) {
            String p = part.strip();
            String id = p.substring(0, p.indexOf(' '));
            Set<String> files = new TreeSet<>();
            Matcher f = Pattern.compile("`([^`]+)`").matcher(p);
            while (f.find()) {
                files.add(f.group(1));
            }
            got.put(id, files);
        }
        assertEquals(want, got, "what students upload on PrairieLearn, per milestone (expected: the assignments)");
    }

    @Test
    void noPlatformSectionNamesAStudentFileOfTheWrongMilestone() throws IOException {
        String doc = Files.readString(DOC);
        Map<String, Set<String>> byMilestone = new LinkedHashMap<>();
        assignmentFiles().forEach((id, files) -> byMilestone.put(id, names(files)));
        Set<String> studentFiles = new TreeSet<>();
        byMilestone.values().forEach(studentFiles::addAll);
        List<String> wrong = new ArrayList<>();
        for (String heading : List.of("## Grading", "### PrairieLearn", "### Classroom 50", "### A whole class: grade-all")) {
            String text = section(doc, heading);
            // "for shadows" / "for lambert" after a list of files: each named file must be the milestone's.
            Matcher m = Pattern.compile("`([A-Za-z]+\\.java)(?:, ([A-Za-z]+\\.java))?` for (\\w+)").matcher(text);
            while (m.find()) {
                String id = m.group(3);
                for (String f : new String[] {m.group(1), m.group(2)}) {
                    if (f != null && studentFiles.contains(f) && byMilestone.containsKey(id)
                            && !byMilestone.get(id).contains(f)) {
                        wrong.add(heading + ": " + f + " for " + id + " (" + id + " grades " + byMilestone.get(id) + ")");
                    }
                }
            }
        }
        assertEquals(List.of(), wrong, "student files named for the wrong milestone");
    }

    @Test
    void thePitVersionInTheDocsIsTheBuilds() throws IOException {
        String pom = Files.readString(Path.of("pom.xml"));
        Matcher v = Pattern.compile("<artifactId>pitest-maven</artifactId>\\s*<version>([^<]+)</version>").matcher(pom);
        assertTrue(v.find(), "pom.xml pins pitest-maven");
        for (Path doc : List.of(DOC, Path.of("grader/README.md"))) {
            Matcher m = Pattern.compile("(?:PIT|pitest-maven)[^0-9\\n]{0,60}?(\\d+\\.\\d+\\.\\d+)").matcher(Files.readString(doc));
            int found = 0;
            while (m.find()) {
                found++;
                assertEquals(v.group(1), m.group(1), doc + " names pitest-maven " + m.group(1) + "; the build uses " + v.group(1));
            }
            assertTrue(found > 0, doc + " names the PIT version");
        }
    }
}
