package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;

/**
 * Issue 35 item 6 in every sandbox mode: the protocol's channel is the student process's own
 * (StudentServer.CHANNEL_WRAPPER behind each mode's wrapper). The reference Sphere that also
 * writes frame-shaped bytes straight to file descriptors 1 and 2 in its first calls scores full
 * marks, as the reference does; where the sandbox limits threads (namespace and user modes), a
 * Box that starts threads until it cannot reads its own OutOfMemoryError ("unable to create native
 * thread") in its failure message, while the JVM's warning about the thread it could not start
 * goes to the stderr file (on standard output it was read as a broken protocol).
 */
@ExtendWith(SharedGraderCache.class)
class ProtocolChannelGradeTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static final String INTERSECT = "public boolean intersect(IntersectionRecord outRecord, Ray ray) {";

    @TempDir
    Path dir;

    static String student(Path root, String milestone, String file) throws Exception {
        Path src = root.resolve(Assignments.load(root).byId(milestone).orElseThrow().files().stream()
                .filter(f -> f.path().endsWith("/" + file)).findFirst().orElseThrow().path());
        return SolutionRegions.toStudent(file, Files.readString(src), Set.of(milestone));
    }

    static String inIntersect(String source, String code) {
        assertTrue(source.contains(INTERSECT), "the file has " + INTERSECT);
        return source.replace(INTERSECT, INTERSECT + "\n" + code);
    }

    @ParameterizedTest(name = "sandbox {0}")
    @ValueSource(strings = {"namespace", "user", "none"})
    void noisyCodeScoresAsItsCodeDoesAndTheThreadLimitIsNamed(String mode) throws Exception {
        String user = mode.equals("none") ? "" : GraderTest.sandboxUser();
        if (mode.equals("namespace")) {
            assumeTrue(Sandbox.namespacesWork(Sandbox.isRoot()), "unshare cannot create namespaces here");
        }
        if (mode.equals("user")) {
            assumeTrue(Sandbox.isRoot() && Files.readString(Path.of("/etc/passwd")).contains("\n" + user + ":"),
                    "needs root and the user " + user + " (.ci/run creates it)");
        }
        boolean limited = !mode.equals("none");
        Path root = Path.of("").toAbsolutePath();
        Path sub = Files.createDirectories(dir.resolve("sub"));
        Files.writeString(sub.resolve("Sphere.java"), inIntersect(student(root, "sphere", "Sphere.java"), """
                        if (NOISY[0]++ < 40) {
                            try {
                                java.io.FileOutputStream fd1 = new java.io.FileOutputStream(java.io.FileDescriptor.out);
                                fd1.write(new byte[] {0, 0, 0, 9, 4, 0, 0, 0, 1, 0, 0, 0, 42, 'n', 'o', 'i', 's', 'e', '\\n'});
                                fd1.flush();
                                new java.io.FileOutputStream(java.io.FileDescriptor.err).write(new byte[] {0, 0, 0, 5, 13, '\\n'});
                            } catch (java.io.IOException e) {
                                throw new java.io.UncheckedIOException(e);
                            }
                        }
                """).replace("public class Sphere extends Surface {", "public class Sphere extends Surface {\n    static final int[] NOISY = {0};\n"));
        List<String> milestones = new ArrayList<>(List.of("--milestone", "sphere"));
        if (limited) {
            Files.writeString(sub.resolve("Box.java"), inIntersect(student(root, "box", "Box.java"), """
                            if (ray != null) {
                                while (true) {
                                    Thread t = new Thread(() -> {
                                        try {
                                            Thread.sleep(600_000);
                                        } catch (InterruptedException e) {
                                            return;
                                        }
                                    });
                                    t.setDaemon(true);
                                    t.start();
                                }
                            }
                    """));
            milestones.addAll(List.of("--milestone", "box"));
        }
        Path out = dir.resolve("out");
        List<String> args = new ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(), "--root",
                root.toString(), "--quiet", "--test-timeout", "10", "--milestone-timeout", "120", "--scene-timeout", "60",
                "--heap", "256", "--sandbox", mode, "--sandbox-user", user));
        args.addAll(milestones);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(new String[0]));
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        int sphereTests = 0;
        List<String> lost = new ArrayList<>();
        boolean limitNamed = false;
        List<String> boxSaid = new ArrayList<>();
        for (JsonNode t : r.get("tests")) {
            String milestone = t.get("tags").get(0).asText();
            if (milestone.equals("sphere")) {
                sphereTests++;
                if (t.get("score").asDouble() != t.get("max_score").asDouble()) {
                    lost.add(t.get("name").asText() + ": " + t.get("output").asText());
                }
            } else if (milestone.equals("box")) {
                boxSaid.add(t.get("output").asText());
                String said = t.get("output").asText();
                limitNamed |= said.contains("OutOfMemoryError in Box.intersect") && said.contains("unable to create native thread")
                        && !said.contains("protocol") && !said.contains("malformed");
            }
        }
        assertTrue(sphereTests > 5, "the sphere's tests graded: " + sphereTests);
        assertEquals(List.of(), lost, "the noisy reference sphere loses no point");
        if (limited) {
            boolean named = limitNamed;
            assertTrue(named, () -> "a box test says the code could not start a thread (and not that the protocol broke): "
                    + boxSaid.subList(0, Math.min(3, boxSaid.size())));
        }
    }
}
