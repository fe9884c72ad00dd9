package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * No visible test's text is withheld: the grader replaces a visible message that contains text
 * found only in the hidden classes by "(withheld: it contains text of the hidden tests)", which
 * leaves a student with a failing visible test and no reason (the shadows test "a lamp standing
 * on the floor …" once said "strictly before the light count", and "before the light" was a
 * hidden test's text). This compiles the hidden tests, collects their text as the grader does
 * (constants of 12 characters or more with a space that no visible class has, split where
 * string concatenation inserts values), and checks that no constant of a visible test or of
 * raylab.testing contains one.
 */
class WithheldTextTest {
    @TempDir
    Path dir;

    static Set<String> pieces(Path classFile) throws IOException {
        Set<String> out = new HashSet<>();
        for (String s : ClassStrings.of(Files.readAllBytes(classFile))) {
            for (String p : s.split("\u0001")) {
                out.add(p);
            }
        }
        return out;
    }

    static List<Path> classes(Path root) throws IOException {
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(p -> p.toString().endsWith(".class")).toList();
        }
    }

    @Test
    void noVisibleTestTextContainsHiddenText() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        List<String> sources = new ArrayList<>();
        try (Stream<Path> s = Files.walk(root.resolve("grader/tests"))) {
            s.filter(p -> p.toString().endsWith(".java")).forEach(p -> sources.add(p.toString()));
        }
        List<String> args = new ArrayList<>(List.of("-nowarn", "-d", dir.toString(), "-cp",
                System.getProperty("java.class.path"), "-sourcepath", "src/test/java" + java.io.File.pathSeparator + "grader/tests"));
        args.addAll(sources);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, args.toArray(String[]::new)),
                "the hidden tests compile");
        Set<String> visible = new HashSet<>();
        Path testClasses = root.resolve("target/test-classes");
        for (Assignment a : Assignments.load(root).all()) {
            for (String v : a.tests().visible()) {
                String rel = v.replaceFirst("^src/test/java/", "").replaceFirst("\\.java$", "");
                Path dirOf = testClasses.resolve(rel).getParent();
                String simple = rel.substring(rel.lastIndexOf('/') + 1);
                try (Stream<Path> s = Files.list(dirOf)) {
                    for (Path c : (Iterable<Path>) s.filter(p -> p.getFileName().toString().startsWith(simple))::iterator) {
                        visible.addAll(pieces(c));
                    }
                }
            }
        }
        for (Path c : classes(testClasses.resolve("raylab/testing"))) {
            visible.addAll(pieces(c));
        }
        Set<String> hidden = new HashSet<>();
        for (Path c : classes(dir)) {
            String rel = dir.relativize(c).toString();
            if (rel.contains("Hidden") || rel.startsWith("raylab/hidden/")) {
                for (String p : pieces(c)) {
                    if (p.length() >= 12 && p.indexOf(' ') >= 0 && !p.isBlank() && !visible.contains(p)) {
                        hidden.add(p);
                    }
                }
            }
        }
        assertTrue(hidden.size() > 20, "hidden text found: " + hidden.size());
        List<String> clashes = new ArrayList<>();
        for (String v : visible) {
            for (String h : hidden) {
                if (v.contains(h)) {
                    clashes.add("visible \"" + v + "\" contains hidden \"" + h + "\"");
                }
            }
        }
        assertTrue(clashes.isEmpty(), "visible messages the grader would withhold:\n  " + String.join("\n  ", clashes));
    }
}
