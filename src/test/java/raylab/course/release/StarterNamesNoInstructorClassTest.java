package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.SourceRoots;
import raylab.grade.ServiceFiles;

/**
 * No class the starter ships names an instructor class in a string (issue 38: the seams between
 * the shipped code and the instructor's are service providers, {@code META-INF/services}, not
 * class names for {@code Class.forName}). Every class compiled from a source file of the starter
 * ({@link Release#build}: {@code src/main/java} and the shipped tests) is read from
 * {@code target/classes} or {@code target/test-classes}, and each string constant of its
 * constant pool (string concatenation's constant parts included) is searched for the name, dotted
 * or with slashes, of a class whose source the starter does not have ({@code src/main/java} files
 * the release leaves out, {@code grader/tests}).
 */
class StarterNamesNoInstructorClassTest {
    private static final Path ROOT = Path.of("");

    @Test
    void noShippedClassNamesAnInstructorClassInAString() throws IOException {
        Set<String> starter = Release.build(ROOT.toAbsolutePath()).files().keySet();
        Set<String> shipped = new TreeSet<>();
        starter.stream().map(StarterNamesNoInstructorClassTest::className).filter(n -> n != null).forEach(shipped::add);
        // The tools ship too, as the starter's jar.
        Set<String> tools = SourceRoots.classesUnder(ROOT.toAbsolutePath(), SourceRoots.TOOLS);
        shipped.addAll(tools);
        Set<String> instructor = new TreeSet<>();
        for (String rel : Release.projectFiles(ROOT.toAbsolutePath())) {
            String name = className(rel);
            if (name != null && !shipped.contains(name)) {
                instructor.add(name);
            }
        }
        assertTrue(instructor.contains("raylab.grade.GradeCommand") && instructor.contains("raylab.boundary.Remote"),
                "the instructor-only classes are found: " + instructor.size() + " of them");
        List<String> found = new ArrayList<>();
        int read = 0;
        List<String> shippedSources = new ArrayList<>(starter);
        tools.forEach(t -> shippedSources.add(SourceRoots.TOOLS + "/" + t.replace('.', '/') + ".java"));
        for (String rel : shippedSources) {
            Path classes = rel.startsWith("src/main/java/") || rel.startsWith("src/tools/java/") ? Path.of("target/classes")
                    : rel.startsWith("src/test/java/") ? Path.of("target/test-classes") : null;
            if (classes == null || !rel.endsWith(".java")) {
                continue;
            }
            String base = rel.substring(rel.indexOf("/java/") + 6, rel.length() - 5);
            List<Path> compiled = compiledClasses(classes, base);
            if (!rel.startsWith("src/test/java/")) {
                assertTrue(!compiled.isEmpty(), rel + " ships, but no class compiled from it is in " + classes);
            }
            for (Path c : compiled) {
                read++;
                for (String s : stringConstants(Files.readAllBytes(c))) {
                    String named = namedClass(s, instructor);
                    if (named != null) {
                        found.add(rel + " (" + c.getFileName() + "): \"" + s + "\" names " + named);
                    }
                }
            }
        }
        assertTrue(read > 100, "read only " + read + " shipped class files");
        assertEquals(List.of(), found, "string constants of shipped classes that name an instructor-only class");
    }

    @Test
    void theStarterHasNoServicesFileOfTheInstructorsProviders() throws IOException {
        Map<String, byte[]> starter = Release.build(ROOT.toAbsolutePath()).files();
        for (String service : List.of("raylab.cli.OptionalCommand", "raylab.surface.PackedEngine",
                "raylab.course.BoundaryHooks")) {
            // Each module registers its providers in its own resources (docs/architecture.md).
            Path file = Stream.of("src/main/resources/", "src/mesh-engine/resources/", "grader/src/main/resources/",
                    "src/authoring/resources/").map(r -> Path.of(r + ServiceFiles.FOLDER + service))
                    .filter(Files::isRegularFile).findFirst().orElse(Path.of(ServiceFiles.SOURCE_FOLDER + service));
            assertTrue(Files.isRegularFile(file) && !ServiceFiles.providers(Files.readString(file)).isEmpty(),
                    "the instructor's tree provides " + service);
            assertEquals(null, starter.get(ServiceFiles.SOURCE_FOLDER + service) == null ? null
                    : new String(starter.get(ServiceFiles.SOURCE_FOLDER + service), StandardCharsets.UTF_8),
                    "the starter lists none of its providers (they are instructor-only)");
        }
    }

    @Test
    void aServicesFileKeepsOnlyTheProvidersThatShip(@TempDir Path dir) throws IOException {
        String text = "# commands\nraylab.grade.GradeCommand\nraylab.surface.PlaneType  # the plane\n\nraylab.boundary.X$Y\n";
        assertEquals(List.of("raylab.grade.GradeCommand", "raylab.surface.PlaneType", "raylab.boundary.X$Y"),
                ServiceFiles.providers(text));
        assertEquals("# commands\nraylab.surface.PlaneType  # the plane\n\n",
                ServiceFiles.keep(text, c -> c.startsWith("raylab.surface.")));
        assertEquals(null, ServiceFiles.keep(text, c -> false), "no provider left: no file");
        assertEquals("raylab/boundary/X.java", ServiceFiles.sourceFile("raylab.boundary.X$Y"));
        // The release verification finds a planted line naming a class the starter lacks.
        Path services = Files.createDirectories(dir.resolve(ServiceFiles.SOURCE_FOLDER));
        Files.writeString(services.resolve("raylab.scene.SurfaceType"), text);
        Files.createDirectories(dir.resolve("src/main/java/raylab/surface"));
        Files.writeString(dir.resolve("src/main/java/raylab/surface/PlaneType.java"), "package raylab.surface;\n");
        List<String> files = List.of("src/main/java/raylab/surface/PlaneType.java",
                ServiceFiles.SOURCE_FOLDER + "raylab.scene.SurfaceType");
        assertEquals(List.of(ServiceFiles.SOURCE_FOLDER + "raylab.scene.SurfaceType:2 lists raylab.grade.GradeCommand,"
                + " which the starter does not have", ServiceFiles.SOURCE_FOLDER + "raylab.scene.SurfaceType:5 lists"
                + " raylab.boundary.X$Y, which the starter does not have"), ReleaseVerifier.unshippedProviders(dir, files));
    }

    @Test
    void theScanFindsAPlantedName() throws IOException {
        // A class file's constant pool with a string naming an instructor class, one naming a shipped
        // class, and a concatenation recipe's constant part with slashes.
        byte[] cls = classFile(List.of("raylab.grade.GradeCommand", "raylab.cli.Main", "see raylab/boundary/Remote\u0001"));
        List<String> strings = stringConstants(cls);
        assertEquals(List.of("raylab.grade.GradeCommand", "raylab.cli.Main", "see raylab/boundary/Remote\u0001"), strings);
        Set<String> instructor = Set.of("raylab.grade.GradeCommand", "raylab.boundary.Remote", "raylab.grade.Grade");
        assertEquals("raylab.grade.GradeCommand", namedClass(strings.get(0), instructor));
        assertEquals(null, namedClass(strings.get(1), instructor));
        assertEquals("raylab.boundary.Remote", namedClass(strings.get(2), instructor));
        assertEquals("raylab.boundary.Remote", namedClass("raylab.boundary.Remote$Hooks", instructor));
        assertEquals(null, namedClass("raylab.boundary.RemoteX", instructor), "a longer name is another class");
        assertEquals(null, namedClass("xraylab.boundary.Remote", instructor));
        assertEquals(null, namedClass("my.raylab.boundary.Remote", instructor), "another package");
    }

    /** The fully qualified name of the class a Java source file defines, or null. */
    static String className(String rel) {
        if (!rel.endsWith(".java") || rel.endsWith("package-info.java") || rel.endsWith("module-info.java")) {
            return null;
        }
        for (String root : List.of("src/main/java/", "src/tools/java/", "src/mesh-engine/java/", "grader/src/main/java/",
                "src/authoring/java/", "src/test/java/", "grader/tests/")) {
            if (rel.startsWith(root)) {
                return rel.substring(root.length(), rel.length() - 5).replace('/', '.');
            }
        }
        return null;
    }

    /** {@code base.class} and its nested classes {@code base$*.class} under {@code classes}. */
    private static List<Path> compiledClasses(Path classes, String base) throws IOException {
        Path dir = classes.resolve(base).getParent();
        String simple = base.substring(base.lastIndexOf('/') + 1);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> {
                String n = p.getFileName().toString();
                return n.equals(simple + ".class") || n.startsWith(simple + "$") && n.endsWith(".class");
            }).sorted().toList();
        }
    }

    /** The instructor class a string names (dotted or with slashes; a nested class by its outer one), or null. */
    static String namedClass(String s, Set<String> instructor) {
        String dotted = s.replace('/', '.');
        for (String name : instructor) {
            for (int k = dotted.indexOf(name); k >= 0; k = dotted.indexOf(name, k + 1)) {
                int end = k + name.length();
                boolean startOk = k == 0 || !namePart(dotted.charAt(k - 1)) && dotted.charAt(k - 1) != '.';
                boolean endOk = end == dotted.length() || dotted.charAt(end) == '$' || !namePart(dotted.charAt(end));
                if (startOk && endOk) {
                    return name;
                }
            }
        }
        return null;
    }

    private static boolean namePart(char c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '$';
    }

    /** The CONSTANT_String entries of a class file's constant pool, in pool order. */
    static List<String> stringConstants(byte[] classFile) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(classFile));
        if (in.readInt() != 0xCAFEBABE) {
            throw new IOException("not a class file");
        }
        in.readUnsignedShort();
        in.readUnsignedShort();
        int count = in.readUnsignedShort();
        String[] utf8 = new String[count];
        List<Integer> strings = new ArrayList<>();
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = in.readUTF();
                case 8 -> strings.add(in.readUnsignedShort());
                case 7, 16, 19, 20 -> in.readUnsignedShort();
                case 15 -> in.skipNBytes(3);
                case 3, 4, 9, 10, 11, 12, 17, 18 -> in.readInt();
                case 5, 6 -> {
                    in.readLong();
                    i++;
                }
                default -> throw new IOException("constant pool tag " + tag + " at entry " + i);
            }
        }
        List<String> out = new ArrayList<>();
        for (int k : strings) {
            out.add(utf8[k]);
        }
        return out;
    }

    /** A minimal class file whose constant pool holds the given strings (enough for {@link #stringConstants}). */
    private static byte[] classFile(List<String> strings) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeInt(0xCAFEBABE);
        out.writeShort(0);
        out.writeShort(61);
        out.writeShort(1 + 2 * strings.size() + 2);
        out.writeByte(5); // a long: two entries
        out.writeLong(42);
        for (int i = 0; i < strings.size(); i++) {
            out.writeByte(1);
            out.writeUTF(strings.get(i));
            out.writeByte(8);
            out.writeShort(3 + 2 * i);
        }
        out.flush();
        return bytes.toByteArray();
    }
}
