package raylab.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.cli.Main;
import raylab.scene.ObjLoader;
import raylab.surface.Group;
import raylab.surface.Mesh;
import raylab.surface.Surface;

/**
 * The bench's rays (the Embree harness's camera) count the same hits and blocked shadow rays
 * through the packed mesh as through a plain Group of its triangles; the procedural mesh equals
 * the harness's OBJ file; {@code raylab bench --obj} prints one JSON line with those counts.
 * (Counts only: timings are never asserted.)
 */
class MeshBenchTest {
    static String obj(double[] tris) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < tris.length; i += 3) {
            s.append("v ").append(tris[i]).append(' ').append(tris[i + 1]).append(' ').append(tris[i + 2]).append('\n');
        }
        for (int i = 0; i < tris.length / 9; i++) {
            s.append("f ").append(3 * i + 1).append(' ').append(3 * i + 2).append(' ').append(3 * i + 3).append('\n');
        }
        return s.toString();
    }

    @Test
    void packedMeshAndAGroupOfTrianglesCountTheSameHits() {
        double[] tris = Icosphere.triangles(3);
        assertEquals(20 * 64, tris.length / 9, "20·4^L triangles");
        Mesh mesh = new Mesh(tris, MeshBench.GREY, "ico3");
        Group group = new Group(new ArrayList<Surface>(mesh.triangles()), "group");
        MeshBench.Pass fast = new MeshBench(mesh, 64, 48).run(2, true);
        MeshBench.Pass slow = new MeshBench(group, 64, 48).run(1, true);
        assertEquals(slow.hits(), fast.hits(), "primary hits");
        assertEquals(slow.occluded(), fast.occluded(), "blocked shadow rays");
        assertEquals(64 * 48 + slow.hits(), fast.rays(), "rays: primary plus one shadow ray per hit");
        assertTrue(fast.hits() > 64 * 48 / 4 && fast.occluded() > 0, "the view sees the mesh and its shadows: " + fast);
    }

    /** A level-2 icosphere (320 triangles) written as an OBJ file. */
    private static Path ico2(Path tmp) throws Exception {
        Path file = tmp.resolve("ico2.obj");
        Files.writeString(file, obj(Icosphere.triangles(2)));
        return file;
    }

    /** The counts of one 40×30 pass with shadows over the file's mesh, traced here directly. */
    private static MeshBench.Pass expectedPass(Path file) throws Exception {
        double[] tris = ObjLoader.read(file, "ico2.obj").triangleVertices();
        return new MeshBench(new Mesh(tris, MeshBench.GREY, "m"), 40, 30).run(1, true);
    }

    /** What {@code raylab bench ARGS} prints, which must exit with status 0. */
    private static String bench(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        String[] all = new String[args.length + 1];
        all[0] = "bench";
        System.arraycopy(args, 0, all, 1, args.length);
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), all);
        assertEquals(0, status, out + "\n" + err);
        return out.toString();
    }

    @Test
    void benchObjPrintsTheCountsAsJson(@TempDir Path tmp) throws Exception {
        Path file = ico2(tmp);
        MeshBench.Pass expected = expectedPass(file);
        String out = bench("--obj", file.toString(), "--size", "40x30", "--runs", "1", "--warmup", "0", "--threads", "2");
        List<String> lines = out.lines().toList();
        String json = lines.get(lines.size() - 1);
        assertTrue(json.startsWith("{\"triangles\":320,\"threads\":2,"), json);
        assertTrue(json.contains("\"hits\":" + expected.hits() + ","), json + " vs " + expected);
        assertTrue(json.contains("\"occluded\":" + expected.occluded() + ","), json + " vs " + expected);
        assertTrue(json.matches(".*\"cpu_primary_median\":[0-9.]+,.*\"cpu_shadow_max\":[0-9.]+}"),
                "rates by the tracing threads' CPU time at the end: " + json);
    }

    @Test
    void benchObjComparesThreadCountsTakenInTurns(@TempDir Path tmp) throws Exception {
        Path file = ico2(tmp);
        MeshBench.Pass expected = expectedPass(file);
        String out = bench("--obj", file.toString(), "--size", "40x30", "--runs", "3", "--warmup", "0", "--threads", "1,2,3");
        List<String> json = out.lines().filter(l -> l.startsWith("{")).toList();
        assertEquals(3, json.size(), "one line per thread count: " + out);
        for (int i = 0; i < 3; i++) {
            String line = json.get(i);
            assertTrue(line.startsWith("{\"triangles\":320,\"threads\":" + (i + 1) + ","), line);
            // Every count traces the same rays, so the counts agree whatever the threads.
            assertTrue(line.contains("\"hits\":" + expected.hits() + ","), line + " vs " + expected);
            assertTrue(line.contains("\"occluded\":" + expected.occluded()), line + " vs " + expected);
            assertEquals(i > 0, line.contains("\"speedup_over_1_threads\":"), "a speed-up for every count but the first: " + line);
        }
        StringWriter err2 = new StringWriter();
        int refused = Main.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err2, true), "bench", "--obj",
                file.toString(), "--runs", "1", "--threads", "1,2");
        assertEquals(2, refused, "a comparison from one run has no interval: " + err2);
        assertEquals(1, err2.toString().lines().count(), err2.toString());
    }
}
