package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;
import raylab.course.SolutionRegions;

/**
 * {@code raylab grade-all} over a class of 20 real submissions built from the corpora under
 * src/test/resources/submissions (the reference in four shapes, correct alternatives, realistic
 * bugs, hostile code, a broken zip, an empty zip, an empty folder, the untouched starter, a
 * compile error, a wrong package, a name that needs escaping), graded on the box milestone only
 * (grading is slow): every submission gets a row, the gradebook's cells are the sums of each
 * student's own results.json, and a second run grades only what is new or unfinished.
 */
@ExtendWith(SharedGraderCache.class)
class GradeAllTest {
    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void gradesAClassAndTheGradebookMatchesEachResult() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Files.setPosixFilePermissions(dir, java.nio.file.attribute.PosixFilePermissions.fromString("rwxr-xr-x"));
        Path subs = Files.createDirectories(dir.resolve("submissions"));
        Path ref = GraderTest.submission(dir, "reference");
        Map<String, Double> expected = new LinkedHashMap<>(); // the box points, where known exactly
        FileTrees.copy(ref, subs.resolve("ref-flat"));
        expected.put("ref-flat", 15.0);
        zip(ref, subs.resolve("ref-zip.zip"), "");
        expected.put("ref-zip", 15.0);
        Path layout = subs.resolve("ref-layout");
        Assignments all = Assignments.load(root);
        for (Assignment a : all.all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path t = layout.resolve(f.path());
                Files.createDirectories(t.getParent());
                Files.copy(ref.resolve(t.getFileName().toString()), t);
            }
        }
        expected.put("ref-layout", 15.0);
        zip(layout, subs.resolve("ref-wrapped.zip"), "raylab-main/");
        expected.put("ref-wrapped", 15.0);
        for (String corpus : List.of("alternatives", "alternatives2", "bugs1", "bugs2", "bugs3", "bugs4", "hostile1", "hostile2")) {
            FileTrees.copy(GraderTest.submission(dir, corpus), subs.resolve(corpus));
        }
        expected.put("alternatives", 15.0);   // no Box.java of its own: the reference box
        expected.put("alternatives2", 15.0);  // the inverse-direction box
        expected.put("bugs2", 15.0);          // its bugs are in other milestones
        expected.put("hostile1", 15.0);       // its attacks are in other milestones
        Path only = Files.createDirectories(subs.resolve("only-box"));
        Files.copy(ref.resolve("Box.java"), only.resolve("Box.java"));
        expected.put("only-box", 15.0);
        Path odd = Files.createDirectories(subs.resolve("=Ann, \"B\" Smith"));
        Files.copy(ref.resolve("Box.java"), odd.resolve("Box.java"));
        expected.put("_Ann___B__Smith", 15.0);
        long seed = 4242L;
        byte[] junk = new byte[4096];
        new Random(seed).nextBytes(junk);
        Files.write(subs.resolve("broken.zip"), junk);
        expected.put("broken", 0.0);
        try (OutputStream os = Files.newOutputStream(subs.resolve("empty-zip.zip")); ZipOutputStream z = new ZipOutputStream(os)) {
            z.setComment("nothing in it");
        }
        expected.put("empty-zip", 0.0);
        Files.createDirectories(subs.resolve("empty-folder"));
        expected.put("empty-folder", 0.0);
        Path starter = Files.createDirectories(subs.resolve("starter"));
        for (Assignment a : all.all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                Files.writeString(starter.resolve(src.getFileName().toString()),
                        SolutionRegions.toStudent(src.getFileName().toString(), Files.readString(src), Set.of()));
            }
        }
        expected.put("starter", 0.0);
        Path syntax = Files.createDirectories(subs.resolve("compile-error"));
        Files.writeString(syntax.resolve("Box.java"), Files.readString(ref.resolve("Box.java")).replace("return", "retur n"));
        expected.put("compile-error", 0.0);
        Path pkg = Files.createDirectories(subs.resolve("wrong-package"));
        Files.writeString(pkg.resolve("Box.java"), Files.readString(ref.resolve("Box.java"))
                .replace("package raylab.surface;", "package raylab.shapes;"));
        expected.put("wrong-package", 0.0);
        try (Stream<Path> s = Files.list(subs)) {
            assertEquals(20, s.count(), "20 submissions");
        }

        Path out = dir.resolve("graded");
        String[] args = {"grade-all", subs.toString(), "--out", out.toString(), "--root", root.toString(), "--jobs", "2",
            "--milestone", "box", "--grade-option=--test-timeout=30", "--grade-option=--milestone-timeout=300",
            "--grade-option=--scene-timeout=120", "--grade-option=--heap=256"};
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(err, true, StandardCharsets.UTF_8), args);
        String log = err.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, () -> "every submission graded: " + log);
        assertTrue(log.contains("[20/20]"), "a line per submission with the progress: " + log);
        assertTrue(log.matches("(?s).*\\[1/20, about \\d+ (s|min) left\\].*"), "the time left: " + log);

        List<String> lines = Files.readAllLines(out.resolve("gradebook.csv"));
        assertEquals("student,box,total,status", lines.get(0));
        assertEquals(21, lines.size(), "one row per student: " + lines);
        Map<String, String[]> rows = new LinkedHashMap<>();
        for (String l : lines.subList(1, lines.size())) {
            String[] c = l.split(",", -1);
            assertEquals(4, c.length, l);
            rows.put(c[0].startsWith("'") ? c[0].substring(1) : c[0], c);
        }
        assertEquals(20, rows.size());
        List<String> bugs = new ArrayList<>();
        for (Map.Entry<String, String[]> e : rows.entrySet()) {
            String student = e.getKey();
            String[] c = e.getValue();
            assertEquals("graded", c[3], "status of " + student);
            JsonNode r = JSON.readTree(out.resolve(student).resolve("results.json").toFile());
            double own = 0;
            for (JsonNode t : r.get("tests")) {
                own += t.get("score").asDouble();
            }
            assertEquals(own, Double.parseDouble(c[1]), 0.005, "the gradebook's box cell of " + student + " is its results.json");
            assertEquals(r.get("score").asDouble(), Double.parseDouble(c[2]), 0.005, "total of " + student);
            if (expected.containsKey(student)) {
                assertEquals(expected.get(student), Double.parseDouble(c[1]), 0.005, () -> student + ": " + r.get("output").asText());
            } else {
                bugs.add(student);
            }
        }
        assertEquals(List.of("bugs1", "bugs3", "bugs4", "hostile2"), bugs.stream().sorted().toList());
        for (String b : bugs) {
            double box = Double.parseDouble(rows.get(b)[1]);
            assertTrue(box < 15, b + " loses points in box: " + box);
        }
        assertTrue(Double.parseDouble(rows.get("bugs3")[1]) > 10, "a realistic bug keeps most points: " + rows.get("bugs3")[1]);

        // Resume: nothing to do; then an unfinished one (no marker) and a changed one are graded again.
        String gradebook = Files.readString(out.resolve("gradebook.csv"));
        err.reset();
        assertEquals(0, Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(err, true, StandardCharsets.UTF_8), args));
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("20 already graded, 0 to grade"), err.toString(StandardCharsets.UTF_8));
        assertEquals(gradebook, Files.readString(out.resolve("gradebook.csv")));
        Files.delete(out.resolve("ref-flat").resolve(".raylab-graded"));
        Files.copy(GraderTest.submission(dir, "bugs4").resolve("Box.java"), subs.resolve("only-box/Box.java"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        err.reset();
        assertEquals(0, Main.run(new PrintWriter(new ByteArrayOutputStream(), true), new PrintWriter(err, true, StandardCharsets.UTF_8), args));
        String again = err.toString(StandardCharsets.UTF_8);
        assertTrue(again.contains("18 already graded, 2 to grade"), again);
        List<String> after = Files.readAllLines(out.resolve("gradebook.csv"));
        assertTrue(after.contains("ref-flat,15,15,graded"), after.toString());
        assertTrue(after.stream().anyMatch(l -> l.startsWith("only-box,") && !l.startsWith("only-box,15,")),
                "the changed submission graded again: " + after);
    }

    static void zip(Path from, Path zip, String prefix) throws Exception {
        try (OutputStream os = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(os);
                Stream<Path> s = Files.walk(from)) {
            for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile).sorted()::iterator) {
                z.putNextEntry(new ZipEntry(prefix + from.relativize(p).toString().replace('\\', '/')));
                z.write(Files.readAllBytes(p));
                z.closeEntry();
            }
        }
    }
}
