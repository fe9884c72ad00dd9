package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.course.FileTrees;
import raylab.course.JavaBuild;

/**
 * Issue 35 item 9: on PrairieLearn nothing secret is reachable under /grade. The job folder is
 * made as PrairieLearn makes it ({@code buildDirectory} in
 * apps/prairielearn/src/lib/externalGraderCommon.ts: serverFilesCourse/raylab, its copy in
 * shared/raylab, tests, student, data/data.json), packed as {@code externalGraderSqs.ts} packs it
 * (a tarball of {@code .}) and extracted as root into a fresh 0700 folder as the grader host does
 * ({@code initFiles} in apps/grader-host/src/index.ts: {@code tar -xf}), which leaves the folder
 * 0755. A probing Box.java then tries to read the grader's jar, a hidden test's source and a
 * reference image in both copies, and to list the folder, and shows what it got in a visible
 * failure message: it must get nothing, while /etc/passwd, which every sandbox mode leaves
 * readable, shows the probe could read and report. PrairieLearn's containers allow only user mode
 * (grader/README.md); namespace mode is graded too where it works.
 */
class PrairieLearnJobFolderIT {
    @TempDir
    Path dir;

    /**
     * Where both cases lay out the job's /grade and keep the grader's cache: the same path for
     * each, as every PrairieLearn job has /grade, so that the cache (keyed by the files' paths)
     * is built once. Each case makes /grade anew.
     */
    @TempDir
    static Path jobs;

    static final String[] SECRETS = {"serverFilesCourse/raylab/raylab.jar", "shared/raylab/raylab.jar",
        "serverFilesCourse/raylab/grader/tests/raylab/surface/BoxHiddenTest.java",
        "shared/raylab/grader/tests/raylab/surface/BoxHiddenTest.java",
        "serverFilesCourse/raylab/scenes/reference/boxes.png", "shared/raylab/scenes/reference/boxes.png"};

    /**
     * A lecture Box (bugs3's) whose intersect first reports, for each path, READ and its size or
     * "no", and whether it could list the job folder.
     */
    static String probe(Path root, Path grade, Path control) throws java.io.IOException {
        StringBuilder paths = new StringBuilder();
        for (String s : SECRETS) {
            paths.append('"').append(grade.resolve(s)).append("\", ");
        }
        paths.append('"').append(control).append('"');
        String method = """
                    private static String probe() {
                        StringBuilder b = new StringBuilder("PROBE");
                        int i = 0;
                        for (String p : new String[] {PATHS}) {
                            b.append(" ").append(i++).append("=");
                            try {
                                int n = java.nio.file.Files.readAllBytes(java.nio.file.Path.of(p)).length;
                                b.append("READ").append(n);
                            } catch (Throwable e) {
                                b.append("no");
                            }
                        }
                        b.append(" list=");
                        try (java.util.stream.Stream<java.nio.file.Path> s = java.nio.file.Files.list(java.nio.file.Path.of("GRADE"))) {
                            long n = s.count();
                            b.append("READ").append(n);
                        } catch (Throwable e) {
                            b.append("no");
                        }
                        return b.append(" END").toString();
                    }
                }
                """.replace("PATHS", paths).replace("GRADE", grade.toString());
        String box = Files.readString(root.resolve("src/test/resources/submissions/bugs3/Box.java"));
        String head = "public boolean intersect(IntersectionRecord outRecord, Ray ray) {";
        assertTrue(box.contains(head), "bugs3's Box has " + head);
        box = box.replace(head, head + "\n        if (ray != null) {\n            throw new IllegalStateException(probe());\n        }");
        return box.substring(0, box.lastIndexOf('}')) + method;
    }

    @ParameterizedTest(name = "sandbox {0}")
    @ValueSource(strings = {"user", "namespace"})
    void aProbingSubmissionGetsNothingOfTheJobFolder(String mode) throws Exception {
        assumeTrue(Sandbox.isRoot(), "PrairieLearn's grader host extracts the job as root; needs root");
        if (mode.equals("namespace")) {
            assumeTrue(Sandbox.namespacesWork(true), "unshare cannot create namespaces here");
        }
        Path root = PlatformBundlesIT.root();
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(jobs, PosixFilePermissions.fromString("rwxr-xr-x"));
        // Built once for all the integration tests (ItBundles: the bundle command's self-check is a grading).
        Path course = ItBundles.prairieLearn(root, Path.of("target/raylab.jar").toAbsolutePath());

        // The job folder as PrairieLearn's buildDirectory makes it, then packed and extracted as root.
        Path job = Files.createDirectories(dir.resolve("job"));
        Path grade = jobs.resolve("grade");
        if (Files.exists(grade)) {
            JavaBuild.deleteTree(grade);
        }
        Files.createDirectory(grade, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
        // A file every sandbox mode leaves readable (namespace mode shows /etc, not /tmp).
        Path control = Path.of("/etc/passwd");
        for (String d : List.of("serverFilesCourse", "tests", "student", "data")) {
            Files.createDirectories(job.resolve(d));
        }
        // With the files' times, as PrairieLearn's every job has the course's files: the cache key holds the jar's time.
        FileTrees.copy(course.resolve("serverFilesCourse/raylab"), job.resolve("serverFilesCourse/raylab"),
                java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
        FileTrees.copy(job.resolve("serverFilesCourse"), job.resolve("shared"));
        Files.writeString(job.resolve("student/Box.java"), probe(root, grade, control));
        Files.writeString(job.resolve("data/data.json"),
                "{\"params\": {}, \"correct_answers\": {}, \"submitted_answers\": {\"_files\": []}}");
        Path log = dir.resolve("pl.log");
        Path tarball = dir.resolve("job.tar.gz");
        assertEquals(0, PlatformBundlesIT.run(dir, Map.of(), log, "tar", "-czf", tarball.toString(), "-C", job.toString(), "."),
                () -> "tar: " + PlatformBundlesIT.read(log));
        assertEquals(0, PlatformBundlesIT.run(dir, Map.of(), log, "tar", "-xf", tarball.toString(), "-C", grade.toString()),
                () -> "tar: " + PlatformBundlesIT.read(log));
        assertEquals("rwxr-xr-x", PosixFilePermissions.toString(Files.getPosixFilePermissions(grade)),
                "extracting the tarball as root gives the folder the archived mode, as on PrairieLearn");
        for (String s : SECRETS) {
            assertTrue(Files.isRegularFile(grade.resolve(s)), "the job folder has " + s);
        }

        List<String> cmd = new ArrayList<>(List.of("bash", grade.resolve("serverFilesCourse/raylab/grade.sh").toString(), "box"));
        int status = PlatformBundlesIT.run(grade, Map.of("RAYLAB_GRADE_ROOT", grade.toString(),
                "RAYLAB_CACHE", jobs.resolve("cache").toString(), "RAYLAB_SANDBOX", mode), log, cmd.toArray(new String[0]));
        assertEquals(0, status, () -> "entrypoint: " + PlatformBundlesIT.read(log));
        String json = Files.readString(grade.resolve("results/results.json"), StandardCharsets.UTF_8);

        Matcher m = Pattern.compile("PROBE (.*?) END").matcher(json);
        assertTrue(m.find(), () -> "the probe's report is in a visible message: " + json.substring(0, Math.min(1500, json.length())));
        Map<String, String> got = new LinkedHashMap<>();
        for (String part : m.group(1).split(" ")) {
            String[] kv = part.split("=", 2);
            got.put(kv[0], kv[1]);
        }
        String controlKey = String.valueOf(SECRETS.length);
        assertEquals("READ" + Files.size(control), got.get(controlKey), () -> "the probe reads " + control + ": " + got);
        for (int i = 0; i < SECRETS.length; i++) {
            assertEquals("no", got.get(String.valueOf(i)), "the probe read " + SECRETS[i] + ": " + got);
        }
        assertEquals("no", got.get("list"), () -> "the probe listed the job folder: " + got);
        assertTrue(Files.notExists(grade.resolve("shared/raylab")), "grade.sh removed the copy in shared/");
    }
}
