package raylab.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.SolutionRegions;
import raylab.render.ImageCompare;
import raylab.render.PngFiles;

/**
 * The course constraint on the packed mesh engine, checked the way the grader and the release
 * verification run student code: a student's {@code Triangle.java} compiled as an overlay over the
 * reference classes, and the triangle milestone's mesh scene rendered in a child JVM.
 * <ul>
 * <li>a student file with the reference's code, word for word, is traced through
 * {@code Triangle.intersect} (its class comes from the overlay, not from the code source of
 * {@code Mesh} and the packed engine) and gives the reference image bit for bit;</li>
 * <li>the same file with a typical bug (the third edge test dropped) gives another image: the bug
 * shows in the mesh;</li>
 * <li>the starter's stub stops the render with exit status 3, naming the milestone.</li>
 * </ul>
 */
class StudentMeshPathTest {
    static final Path TRIANGLE = Path.of("src/main/java/raylab/surface/Triangle.java");
    static final Path SCENE = Path.of("scenes/mesh.json");
    static final Path REFERENCE = Path.of("scenes/reference/mesh.png");

    static BufferedImage render(String triangleSource, Path dir, String name, int[] exit, String[] message)
            throws Exception {
        Path src = dir.resolve(name + "-src");
        Path out = dir.resolve(name + "-classes");
        JavaBuild.Result built = MilestoneBuild.compileOverlay(Map.of("raylab/surface/Triangle.java", triangleSource),
                src, JavaBuild.ownClassPath(), out);
        assertTrue(built.success(), name + ": compiles: " + built.errors());
        Path png = dir.resolve(name + ".png");
        MilestoneBuild.RenderOutcome r = MilestoneBuild.renderInChild(MilestoneBuild.classPath(out), SCENE, png,
                Duration.ofMinutes(4), 512, dir);
        exit[0] = r.exitStatus();
        message[0] = r.message();
        return r.exitStatus() == 0 ? PngFiles.read(png) : null;
    }

    static long differentPixels(BufferedImage a, BufferedImage b) {
        long n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    n++;
                }
            }
        }
        return n;
    }

    @Test
    void studentTrianglesAreWhatTheMeshSceneShows(@TempDir Path dir) throws Exception {
        String reference = Files.readString(TRIANGLE, StandardCharsets.UTF_8);
        BufferedImage expected = PngFiles.read(REFERENCE);
        int[] exit = new int[1];
        String[] message = new String[1];

        String asStudent = SolutionRegions.toStudent("Triangle.java", reference, Set.of("triangle"));
        BufferedImage same = render(asStudent, dir, "correct", exit, message);
        assertEquals(0, exit[0], "correct student file renders: " + message[0]);
        assertEquals(0, differentPixels(expected, same),
                "Triangle.intersect objects and the packed kernel give the same mesh image, bit for bit");

        String bug = "if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) {";
        assertTrue(asStudent.contains(bug), "the edge test to break is in Triangle.java");
        String broken = asStudent.replace(bug, "if ((e0 < 0 || e1 < 0) && (e0 > 0 || e1 > 0)) {");
        BufferedImage wrong = render(broken, dir, "broken", exit, message);
        assertEquals(0, exit[0], "broken student file still renders: " + message[0]);
        long differ = differentPixels(expected, wrong);
        ImageCompare.Result cmp = ImageCompare.compare(wrong, expected);
        System.out.println("broken Triangle: " + differ + " pixels differ; " + cmp.summary());
        assertFalse(cmp.matches(0.005), "the grader's tolerance must catch the broken triangle: " + cmp.summary());

        String stub = SolutionRegions.toStudent("Triangle.java", reference, Set.of());
        assertEquals(null, render(stub, dir, "stub", exit, message));
        assertEquals(3, exit[0], "the stub stops the mesh render: " + message[0]);
        assertTrue(message[0].contains("triangle"), "the message names the milestone: " + message[0]);
    }

    @Test
    void theReferenceBuildUsesThePackedEngine() throws ClassNotFoundException {
        assertTrue(Mesh.PACKED_ENGINE, "reference build: Triangle, Mesh and PackedTriangles share one code source");
        assertTrue(Mesh.sameOrigin(Triangle.class, Class.forName("raylab.mesh.PackedTriangles")), "same class folder");
    }

    @Test
    void aStudentTriangleCannotClaimThePackedEngine(@TempDir Path dir) throws Exception {
        // A Triangle that declares what the former marker was, and more: still its own kernel.
        String reference = Files.readString(TRIANGLE, StandardCharsets.UTF_8);
        String forged = SolutionRegions.toStudent("Triangle.java", reference, Set.of("triangle")).replace(
                "    @Override\n    public BoundingBox boundingBox()",
                "    static final boolean REFERENCE_KERNEL = true;\n    static final boolean PACKED_ENGINE = true;\n\n"
                        + "    @Override\n    public BoundingBox boundingBox()");
        assertTrue(forged.contains("REFERENCE_KERNEL"), "the forged marker is in the file");
        Path src = dir.resolve("forged-src");
        Path out = dir.resolve("forged-classes");
        JavaBuild.Result built = MilestoneBuild.compileOverlay(Map.of("raylab/surface/Triangle.java", forged), src,
                JavaBuild.ownClassPath(), out);
        assertTrue(built.success(), "compiles: " + built.errors());
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", MilestoneBuild.classPath(out).stream().map(Path::toString)
                .collect(java.util.stream.Collectors.joining(java.io.File.pathSeparator)), ProbeMain.class.getName()));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.redirectErrorStream(true);
        Process p = pb.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertEquals(0, p.waitFor(), "probe ran: " + output);
        assertEquals("packed=false", output, "a Triangle from the overlay selects the student kernel");
    }

    /** Run in a child JVM: which kernel a mesh of this class path's Triangle objects uses. */
    public static final class ProbeMain {
        public static void main(String[] args) {
            System.out.println("packed=" + Mesh.PACKED_ENGINE);
        }
    }
}
