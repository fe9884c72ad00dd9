package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;

/**
 * The Gradescope bundle, unzipped into a directory laid out like Gradescope's (source,
 * submission, results under one root), grades a sample submission offline with run_autograder.
 * Runs after `package` (an integration test of `./mvnw verify`): it bundles target/raylab.jar.
 */
class BundleIT {
    @TempDir
    Path dir;

    @Test
    void unzippedBundleGradesASubmissionOffline() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path jar = Path.of("target/raylab.jar").toAbsolutePath();
        assertTrue(Files.isRegularFile(jar), "needs target/raylab.jar: run with ./mvnw verify, which packages it first");
        // Like /autograder on Gradescope: traversable by the unprivileged user (JUnit makes it 700).
        Files.setPosixFilePermissions(dir, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        Path zip = dir.resolve("autograder.zip");
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(System.err, true),
                "bundle", "gradescope", "--out", zip.toString(), "--root", root.toString(), "--jar", jar.toString());
        assertEquals(0, status);
        Path ag = dir.resolve("autograder");
        Path source = Files.createDirectories(ag.resolve("source"));
        Set<String> names = new java.util.HashSet<>();
        try (InputStream in = Files.newInputStream(zip); ZipInputStream z = new ZipInputStream(in)) {
            for (ZipEntry e; (e = z.getNextEntry()) != null;) {
                names.add(e.getName());
                Path t = source.resolve(e.getName()).normalize();
                assertTrue(t.startsWith(source));
                Files.createDirectories(t.getParent());
                Files.copy(z, t);
            }
        }
        assertTrue(names.containsAll(Set.of("setup.sh", "run_autograder", "raylab.jar")), "bundle has " + names);
        // A sample submission: the reference files of milestone lambert only (the others score 0).
        Path sub = Files.createDirectories(ag.resolve("submission"));
        Assignment lambert = Assignments.load(root).byId("lambert").orElseThrow();
        for (Assignment.StudentFile f : lambert.files()) {
            Path src = root.resolve(f.path());
            String name = src.getFileName().toString();
            Files.writeString(sub.resolve(name),
                    SolutionRegions.toStudent(name, Files.readString(src), Set.of("lambert")));
        }
        ProcessBuilder pb = new ProcessBuilder("bash", source.resolve("run_autograder").toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile());
        pb.environment().put("AUTOGRADER_ROOT", ag.toString());
        Process p = pb.start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "run_autograder finished");
        JsonNode r = new ObjectMapper().readTree(ag.resolve("results/results.json").toFile());
        GraderTest.checkSchema(r);
        double lambertScore = 0;
        double lambertMax = 0;
        for (JsonNode t : r.get("tests")) {
            if (t.get("tags").get(0).asText().equals("lambert")) {
                lambertScore += t.get("score").asDouble();
                lambertMax += t.get("max_score").asDouble();
            }
        }
        assertTrue(lambertMax > 0, "lambert graded: " + r.get("output").asText());
        assertEquals(lambertMax, lambertScore, 1e-6, () -> "lambert full marks: " + r.get("output").asText());
    }
}
