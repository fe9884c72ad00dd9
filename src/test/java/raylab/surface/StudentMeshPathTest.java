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
 * <li>a student file with the reference's code (but not its marker) is traced through
 * {@code Triangle.intersect} and gives the reference image bit for bit;</li>
 * <li>the same file with a typical bug (the third edge test dropped) gives another image: the bug
 * shows in the mesh;</li>
 * <li>the starter's stub stops the render with exit status 3, naming the milestone.</li>
 * </ul>
 */
class StudentMeshPathTest {
    static final Path TRIANGLE = Path.of("src/main/java/raylab/surface/Triangle.java");
    static final Path SCENE = Path.of("scenes/mesh.json");
    static final Path REFERENCE = Path.of("scenes/reference/mesh.png");

    /** The reference solution as a student could have written it: without the marker. */
    static String withoutMarker(String reference) {
        String marker = "    static final boolean REFERENCE_KERNEL = true;\n";
        assertTrue(reference.contains(marker), "the marker is in Triangle.java");
        return reference.replace(marker, "");
    }

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

        String asStudent = withoutMarker(SolutionRegions.toStudent("Triangle.java", reference, Set.of("triangle")));
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
        assertFalse(stub.contains("REFERENCE_KERNEL"), "the starter has no marker");
        assertEquals(null, render(stub, dir, "stub", exit, message));
        assertEquals(3, exit[0], "the stub stops the mesh render: " + message[0]);
        assertTrue(message[0].contains("triangle"), "the message names the milestone: " + message[0]);
    }

    @Test
    void theStarterHasNoMarkerAndTheReferenceHasIt() throws Exception {
        String reference = Files.readString(TRIANGLE, StandardCharsets.UTF_8);
        assertTrue(Mesh.REFERENCE_TRIANGLE, "reference build: meshes use the packed kernel");
        for (String milestone : List.of("sphere", "box", "lambert")) {
            assertFalse(SolutionRegions.toStudent("Triangle.java", reference, Set.of(milestone)).contains("REFERENCE_KERNEL"),
                    "starter (with " + milestone + " solved)");
        }
    }
}
