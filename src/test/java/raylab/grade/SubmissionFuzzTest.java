package raylab.grade;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.Submission;
import raylab.fuzzing.OneLine;

/**
 * Fuzzes the grader's intake of a submission ({@link Submission#read}, its public API): the input
 * is either a zip built from fuzzed entry names and contents (Java sources with fuzzed package
 * lines among them) or raw fuzzed bytes given as a zip. The property: it returns the files it
 * accepts, each one of the assignments' student files with the right package, or throws an
 * IOException whose message is one line; never another exception or error. Saved inputs:
 * src/test/resources/raylab/grade/SubmissionFuzzTestInputs/submission.
 */
class SubmissionFuzzTest {
    static List<Assignment> assignments;
    static Path dir;

    @BeforeAll
    static void load() throws IOException {
        assignments = Assignments.load(Path.of(".")).all();
        dir = Files.createTempDirectory("raylab-submission-fuzz");
    }

    @AfterAll
    static void cleanUp() throws IOException {
        Files.deleteIfExists(dir.resolve("submission.zip"));
        Files.deleteIfExists(dir);
    }

    @FuzzTest(maxDuration = "60s")
    void submission(FuzzedDataProvider in) throws IOException {
        Path zip = dir.resolve("submission.zip");
        Files.write(zip, in.consumeBoolean() ? zipOf(in) : in.consumeRemainingAsBytes());
        Submission s;
        try {
            s = Submission.read(zip, assignments);
        } catch (IOException e) {
            OneLine.check(e.getMessage(), null, false, e);
            return;
        }
        for (Map.Entry<String, String> f : s.files().entrySet()) {
            boolean editable = assignments.stream().flatMap(a -> a.files().stream())
                    .anyMatch(sf -> sf.path().equals(f.getKey()));
            if (!editable || f.getValue() == null || !s.sources().containsKey(f.getKey())) {
                throw new AssertionError("accepted a file that is not a student file: " + f.getKey());
            }
        }
        for (String why : s.ignored()) {
            OneLine.check(why, null, false, null);
        }
    }

    /** A zip of up to 8 entries: fuzzed names (often a student file's), fuzzed Java text. */
    private static byte[] zipOf(FuzzedDataProvider in) throws IOException {
        String[] names = {"Sphere.java", "src/main/java/raylab/surface/Box.java", "raylab/surface/Triangle.java",
            "x/Lambertian.java", "__MACOSX/._Sphere.java", "../Shadows.java"};
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipOutputStream z = new ZipOutputStream(bytes)) {
            int n = in.consumeInt(0, 8);
            for (int i = 0; i < n; i++) {
                String name = in.consumeBoolean() ? names[in.consumeInt(0, names.length - 1)] : in.consumeString(40);
                if (name.isEmpty()) {
                    name = "empty";
                }
                try {
                    z.putNextEntry(new ZipEntry(name));
                } catch (java.util.zip.ZipException duplicate) {
                    continue;
                }
                String pkg = in.consumeBoolean() ? "package raylab.surface;\n" : in.consumeString(60);
                z.write((in.consumeString(200) + pkg + in.consumeString(200)).getBytes(
                        java.nio.charset.StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        return bytes.toByteArray();
    }
}
