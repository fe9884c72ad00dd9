package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;
import raylab.remote.StudentServer;

/**
 * The differential test of issue 35 (grader/README.md, "What crosses the boundary"): every
 * milestone's scenes are rendered through the process boundary, batched, with the reference of
 * the milestone's graded methods as it is and perturbed (each answer one ulp or one colour step
 * off: {@link Speculation#PERTURB}), for the reference solution, a buggy and a hostile
 * submission (src/test/resources/submissions/forgers/, armed); the student process records every byte it receives
 * ({@link StudentServer#RECORD}), and the two recordings must be the same, byte for byte. A
 * value computed by the reference, or derived from its state, that reached the student's
 * process would differ. A milestone's stand-ins are compiled once, for its three submissions.
 */
class BoundaryDifferentialTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path ROOT = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();

    /** Each milestone with its reference, one buggy and one hostile submission. */
    static Stream<Arguments> gradings() throws Exception {
        List<Arguments> all = new ArrayList<>();
        try (Stream<Path> dirs = Files.list(ROOT.resolve("assignments"))) {
            for (Path d : dirs.filter(p -> Files.isRegularFile(p.resolve("assignment.json"))).sorted().toList()) {
                JsonNode a = JSON.readTree(d.resolve("assignment.json").toFile());
                String id = a.get("id").asText();
                all.add(Arguments.of(id, "reference"));
                all.add(Arguments.of(id, buggy(a)));
                all.add(Arguments.of(id, "forgers"));
            }
        }
        return all.stream();
    }

    /** The first bundled buggy submission with a file of this milestone. */
    private static String buggy(JsonNode assignment) {
        for (String s : List.of("bugs1", "bugs2", "bugs3", "bugs4", "mistakes")) {
            for (JsonNode f : assignment.get("files")) {
                Path p = Path.of(f.get("path").asText());
                if (Files.isRegularFile(ROOT.resolve("src/test/resources/submissions/" + s).resolve(p.getFileName()))) {
                    return s;
                }
            }
        }
        throw new AssertionError("no buggy submission has a file of " + assignment.get("id"));
    }

    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("gradings")
    void theStudentProcessReceivesTheSameBytesWhateverTheReferenceAnswers(String milestone, String submission,
            @TempDir Path dir) throws Exception {
        JsonNode a = null;
        try (Stream<Path> dirs = Files.list(ROOT.resolve("assignments"))) {
            for (Path d : dirs.filter(p -> Files.isRegularFile(p.resolve("assignment.json"))).toList()) {
                JsonNode x = JSON.readTree(d.resolve("assignment.json").toFile());
                if (x.get("id").asText().equals(milestone)) {
                    a = x;
                }
            }
        }
        assertTrue(a != null, "assignment " + milestone);
        Map<String, String> standInSources = new HashMap<>();
        Map<String, String> studentSources = new HashMap<>();
        Set<String> served = new LinkedHashSet<>();
        Path references = dir.resolve("ref");
        Path classes = Path.of(Speculation.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        for (JsonNode f : a.get("files")) {
            String path = f.get("path").asText();
            String rel = path.substring("src/main/java/".length());
            String fqcn = rel.substring(0, rel.length() - ".java".length()).replace('/', '.');
            Set<String> methods = new LinkedHashSet<>();
            for (JsonNode m : f.get("methods")) {
                methods.add(m.asText().substring(m.asText().indexOf('.') + 1));
            }
            String source = Files.readString(ROOT.resolve(path));
            standInSources.put(rel, StandIns.forwarding(SolutionRegions.toStudent(rel, source, Set.of()), fqcn, methods));
            Path own = ROOT.resolve("src/test/resources/submissions/" + submission).resolve(Path.of(path).getFileName());
            studentSources.put(rel, !submission.equals("reference") && Files.isRegularFile(own)
                    ? Files.readString(own).replace("@ARMED@", "true") : source);
            served.add(fqcn);
            // The reference's classes of the file (the predictors), alone.
            String cls = rel.substring(0, rel.length() - ".java".length());
            Path parent = classes.resolve(cls).getParent();
            String simple = Path.of(cls).getFileName().toString();
            Files.createDirectories(references.resolve(cls).getParent());
            try (Stream<Path> files = Files.list(parent)) {
                for (Path c : files.filter(p -> p.getFileName().toString().equals(simple + ".class")
                        || p.getFileName().toString().startsWith(simple + "$")).toList()) {
                    Files.copy(c, references.resolve(cls).getParent().resolve(c.getFileName()));
                }
            }
        }
        Path standIns = STAND_INS.compile(standInSources, shared.resolve("standins-" + milestone));
        Path student = dir.resolve("student");
        StandIns.compile(studentSources, StudentProcessTest.classDirs(), student);
        // The milestone's scenes at a tenth of their size, beside the meshes they name.
        Path scenes = dir.resolve("scenes");
        Files.createDirectories(scenes);
        Files.createSymbolicLink(scenes.resolve("meshes"), ROOT.resolve("scenes/meshes"));
        List<String> triples = new ArrayList<>();
        for (JsonNode s : a.get("scenes")) {
            String name = s.get("scene").asText();
            ObjectNode scene = (ObjectNode) JSON.readTree(ROOT.resolve(name).toFile());
            ObjectNode image = (ObjectNode) scene.get("image");
            image.put("width", Math.max(8, image.get("width").asInt() / 10));
            image.put("height", Math.max(6, image.get("height").asInt() / 10));
            Path small = scenes.resolve(Path.of(name).getFileName());
            JSON.writeValue(small.toFile(), scene);
            triples.add(small.toString());
            triples.add("OUT/" + Path.of(name).getFileName() + ".png");
            triples.add(name);
        }
        Run plain = render(dir.resolve("plain"), standIns, references, student, served, triples, false);
        Run perturbed = render(dir.resolve("perturbed"), standIns, references, student, served, triples, true);
        String what = milestone + " graded with " + submission;
        assertTrue(plain.frames().length > 0, () -> what + ": frames were recorded; log: " + plain.shortLog());
        assertEquals(plain.errors(), perturbed.errors(), what + ": the renders' error lines, plain and perturbed");
        if (plain.rendered()) {
            // Counts are printed for a scene rendered to its end.
            assertTrue(plain.predictions() > 0 && perturbed.predictions() > 0, () -> what
                    + ": the reference answered (the reference images); logs: " + plain.shortLog() + perturbed.shortLog());
            assertTrue(!plain.log().contains("batches 0,"), () -> what + ": the calls went in MULTI frames; log: "
                    + plain.shortLog());
        }
        assertEquals(plain.frames().length, perturbed.frames().length,
                () -> what + ": bytes received by the student process, with the reference as it is (expected) and"
                        + " perturbed (actual); first difference at byte " + firstDifference(plain.frames(),
                                perturbed.frames()));
        assertArrayEquals(plain.frames(), perturbed.frames(), () -> what
                + ": the bytes the student process received, with the reference as it is (expected) and perturbed"
                + " (actual); first difference at byte " + firstDifference(plain.frames(), perturbed.frames()));
    }

    /** The stand-ins of each milestone, compiled once per class run (the same for its three submissions). */
    @TempDir
    static Path shared;
    private static final CompiledOnce STAND_INS = new CompiledOnce();

    private static int firstDifference(byte[] a, byte[] b) {
        int n = Math.min(a.length, b.length);
        for (int i = 0; i < n; i++) {
            if (a[i] != b[i]) {
                return i;
            }
        }
        return n;
    }

    private record Run(byte[] frames, String errors, String log) {
        boolean rendered() {
            return log.contains("batches ");
        }

        String shortLog() {
            return log.length() > 2000 ? log.substring(0, 2000) + " ..." : log;
        }

        long predictions() {
            long sum = 0;
            Matcher m = Pattern.compile("predictions (\\d+)").matcher(log);
            while (m.find()) {
                sum += Long.parseLong(m.group(1));
            }
            return sum;
        }
    }

    private static Run render(Path out, Path standIns, Path references, Path student, Set<String> served,
            List<String> triples, boolean perturb) throws Exception {
        Files.createDirectories(out.resolve("OUT"));
        List<Path> studentPath = new ArrayList<>();
        studentPath.add(student);
        studentPath.addAll(StudentProcessTest.classDirs());
        List<String> studentCmd = new ArrayList<>(StudentJvm.javaCommand(studentPath, 128, List.copyOf(served)));
        Path frames = out.resolve("frames.bin");
        // After the java binary (the command may start with the channel's wrapper).
        int java = 0;
        while (!studentCmd.get(java).endsWith("/bin/java")) {
            java++;
        }
        studentCmd.add(java + 1, "-D" + StudentServer.RECORD + "=" + frames);
        Path config = out.resolve("student.properties");
        Remote.writeConfig(config, new StudentProcess.Config(studentCmd, null, served, 60_000, 1));
        List<String> cp = new ArrayList<>();
        cp.add(standIns.toString());
        cp.add(System.getProperty("java.class.path"));
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-Draylab.boundary=" + config, "-Djava.awt.headless=true",
                "-Draylab.boundary.references=" + references, "-D" + Speculation.PERTURB + "=" + perturb,
                "-cp", String.join(File.pathSeparator, cp), "raylab.boundary.TrustedRender"));
        for (int i = 0; i < triples.size(); i++) {
            cmd.add(i % 3 == 1 ? out.resolve(triples.get(i)).toString() : triples.get(i));
        }
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).directory(out.toFile())
                .redirectOutput(out.resolve("log.txt").toFile());
        pb.environment().put("RAYLAB_GRADE_TIMES", "1"); // the counts of each batched render
        Process p = pb.start();
        assertTrue(p.waitFor(600, TimeUnit.SECONDS), "the renders finished");
        StringBuilder errors = new StringBuilder();
        for (int i = 1; i < triples.size(); i += 3) {
            Path err = Path.of(out.resolve(triples.get(i)) + ".err");
            errors.append(triples.get(i)).append(": ")
                    .append(Files.isRegularFile(err) ? Files.readString(err, StandardCharsets.UTF_8) : "").append('\n');
        }
        return new Run(Files.isRegularFile(frames) ? Files.readAllBytes(frames) : new byte[0], errors.toString(),
                Files.readString(out.resolve("log.txt"), StandardCharsets.UTF_8));
    }
}
