package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.SolutionRegions;

/**
 * No reference method body in the starter: a copy of a reference method under another name in
 * another class of a fake starter is found by its bytecode and by its tokens; the same starter
 * without the copy is clean; and the real starter of this tree is clean.
 */
class SolutionLeaksTest {
    @TempDir
    Path dir;

    private static final String SHAPE = """
            package demo;

            public class Shape {
                public double hit(double a, double b, double c) {
                    // BEGIN SOLUTION shape
                    double disc = b * b - 4 * a * c;
                    if (disc < 0) {
                        return Double.NaN;
                    }
                    double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
                    double t0 = q / a;
                    double t1 = c / q;
                    return Math.min(t0, t1) > 0 ? Math.min(t0, t1) : Math.max(t0, t1);
                    // STUB
                    // throw new UnsupportedOperationException("hit");
                    // END SOLUTION
                }

                public double size() {
                    return 1;
                }
            }
            """;

    /** The copy: the reference body under another name, in another class, another layout, a comment. */
    private static final String HELPER_WITH_COPY = """
            package demo;

            final class Helper {
                double roots(double a, double b, double c) { // "a fast path"
                    double disc = b * b - 4 * a * c;
                    if (disc < 0) { return Double.NaN; }
                    double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
                    double t0 = q / a; double t1 = c / q;
                    return Math.min(t0, t1) > 0 ? Math.min(t0, t1) : Math.max(t0, t1);
                }
            }
            """;

    /** The same with every variable renamed: the tokens differ, the bytecode does not. */
    private static final String HELPER_WITH_RENAMED_COPY = """
            package demo;

            final class Helper {
                double roots(double x, double y, double z) {
                    double d = y * y - 4 * x * z;
                    if (d < 0) {
                        return Double.NaN;
                    }
                    double h = -0.5 * (y + Math.copySign(Math.sqrt(d), y));
                    double near = h / x;
                    double far = z / h;
                    return Math.min(near, far) > 0 ? Math.min(near, far) : Math.max(near, far);
                }
            }
            """;

    private static final String HELPER_CLEAN = """
            package demo;

            final class Helper {
                static double roots(double x, double y, double z) {
                    return x + y + z;
                }
            }
            """;

    /** A fake starter (the stub of Shape and the helper), its build, and the solution's build. */
    private List<SolutionLeaks.Leak> leaks(String helper) throws IOException {
        Path starter = dir.resolve("starter");
        Path src = Files.createDirectories(starter.resolve("src/main/java/demo"));
        Files.writeString(src.resolve("Shape.java"), SolutionRegions.toStudent("Shape.java", SHAPE, java.util.Set.of()));
        Files.writeString(src.resolve("Helper.java"), helper);
        Path main = dir.resolve("starter-main");
        JavaBuild.Result s = MilestoneBuild.compileTree(starter.resolve("src/main/java"), List.of(), main);
        assertTrue(s.success(), "the fake starter compiles: " + s.errors());
        Path solution = dir.resolve("solution");
        JavaBuild.Result r = MilestoneBuild.compileOverlay(Map.of("demo/Shape.java",
                SolutionRegions.toStudent("Shape.java", SHAPE, java.util.Set.of("shape"))), dir.resolve("solution-src"),
                List.of(main), solution);
        assertTrue(r.success(), "the solution compiles: " + r.errors());
        List<SolutionLeaks.Leak> out = new java.util.ArrayList<>(SolutionLeaks.inBytecode(solution, main, List.of(main)));
        out.addAll(SolutionLeaks.inSources(Map.of("src/main/java/demo/Shape.java", SHAPE), starter));
        return out;
    }

    @Test
    void aReferenceMethodCopiedUnderAnotherNameIsFound() throws IOException {
        List<SolutionLeaks.Leak> found = leaks(HELPER_WITH_COPY);
        assertEquals(2, found.size(), "one leak by bytecode, one by source: " + found);
        assertEquals("bytecode: demo.Shape: public double hit(double, double, double); is in demo.Helper: "
                + "double roots(double, double, double);", found.get(0).toString());
        assertEquals("source", found.get(1).kind(), found.toString());
        assertTrue(found.get(1).foundIn().startsWith("src/main/java/demo/Helper.java"), found.get(1).foundIn());
    }

    @Test
    void aCopyWithRenamedVariablesIsFoundByItsBytecode() throws IOException {
        List<SolutionLeaks.Leak> found = leaks(HELPER_WITH_RENAMED_COPY);
        assertEquals(List.of("bytecode: demo.Shape: public double hit(double, double, double); is in demo.Helper: "
                + "double roots(double, double, double);"), found.stream().map(Object::toString).toList());
    }

    @Test
    void aStarterWithoutTheCopyIsClean() throws IOException {
        assertEquals(List.of(), leaks(HELPER_CLEAN));
    }

    @Test
    void tokensDropCommentsAndLayout() {
        assertEquals(List.of("double", "t", "=", "q", "/", "a", ";", "String", "s", "=", "\"x // y\"", ";", "1.5e-3"),
                SolutionLeaks.tokens("double t=q /a; // c\n/* d */ String s = \"x // y\";\n 1.5e-3"));
    }

    /**
     * The real starter. Before the mesh change of issue 17 (the packed kernel moved to the
     * instructor-only PackedTriangles) this listed exactly the leak: Triangle's reference
     * {@code differenceOfProducts} in {@code Mesh.java}, by bytecode and by source.
     */
    @Test
    void theRealStarterHoldsNoReferenceMethod() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path starter = dir.resolve("real");
        Release.write(root, starter, false);
        Path main = dir.resolve("real-main");
        List<Path> libs = ReleaseVerifier.libraries();
        JavaBuild.Result s = MilestoneBuild.compileTree(starter.resolve("src/main/java"), libs, main);
        assertTrue(s.success(), "the starter compiles: " + s.errors());
        List<SolutionLeaks.Leak> found = SolutionLeaks.find(root, starter, Assignments.load(root), main, List.of(main),
                libs, dir.resolve("leaks"));
        assertEquals(List.of(), found, "reference code in the starter");
    }
}
