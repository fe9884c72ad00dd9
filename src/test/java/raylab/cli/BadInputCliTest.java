package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.render.Image;

/**
 * Bad command lines, each answered before any rendering with exit status 2, one line naming the
 * file, and nothing left behind: outputs that are not regular files, missing or read-only
 * folders, images too large for the heap, mesh names the locale cannot encode, a submission that
 * does not exist, option values with line breaks.
 */
class BadInputCliTest {
    @TempDir
    Path dir;

    record Run(int status, String out, String err) {
    }

    static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new Run(status, out.toString(), err.toString());
    }

    /** Exit 2, exactly the expected line on stderr, nothing rendered (no plan printed). */
    static void refusedBeforeRendering(Run r, String expectedLine) {
        assertEquals(2, r.status(), () -> "exit status; stderr: " + r.err());
        assertEquals(expectedLine, r.err().strip());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertFalse(r.out().contains("plan:"), () -> "rendered before refusing: " + r.out());
    }

    static List<String> listing(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void outputOntoADeviceIsRefusedAndTheDeviceKept() {
        Path devNull = Path.of("/dev/null");
        assumeTrue(Files.exists(devNull));
        Run r = run("render", "scenes/sphere.json", "-o", "/dev/null");
        refusedBeforeRendering(r, "raylab: -o /dev/null: is not a regular file (a device, pipe or socket);"
                + " raylab writes images only to regular files or new paths");
        assertFalse(Files.isRegularFile(devNull, LinkOption.NOFOLLOW_LINKS), "/dev/null is still a device");
    }

    @Test
    void outputOntoADirectoryOrALinkIsRefused() throws IOException {
        Path sub = Files.createDirectory(dir.resolve("sub"));
        refusedBeforeRendering(run("render", "scenes/sphere.json", "-o", sub.toString()),
                "raylab: -o " + sub + ": is a directory; give the name of a PNG file in it");
        Path target = Files.writeString(dir.resolve("real.png"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), target);
        refusedBeforeRendering(run("render", "scenes/sphere.json", "-o", link.toString()),
                "raylab: -o " + link + ": is a symbolic link; give the path of the file itself");
        assertEquals("old", Files.readString(target));
        assertEquals(List.of("link.png", "real.png", "sub"), listing(dir));
    }

    @Test
    void outputIntoAMissingFolderIsRefusedBeforeRendering() throws IOException {
        Path out = dir.resolve("missing").resolve("x.png");
        refusedBeforeRendering(run("render", "scenes/sphere.json", "-o", out.toString()),
                "raylab: -o " + out + ": cannot be written: the folder " + out.getParent()
                        + " does not exist (create it first)");
        assertEquals(List.of(), listing(dir));
    }

    @Test
    void outputIntoAReadOnlyFolderIsRefusedBeforeRenderingWithTheReason() throws IOException {
        Path folder;
        boolean root = "root".equals(System.getProperty("user.name"));
        if (root) {
            folder = Path.of("/sys"); // not writable even for root (permission bits do not stop root)
            assumeTrue(Files.isDirectory(folder), "no /sys here");
        } else {
            folder = Files.createDirectory(dir.resolve("ro"));
            Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("r-xr-xr-x"));
        }
        Path out = folder.resolve("x.png");
        Run r = run("render", "scenes/sphere.json", "-o", out.toString());
        refusedBeforeRendering(r, "raylab: -o " + out + ": cannot be written: the folder " + folder
                + " is not writable (permission denied)");
        assertFalse(Files.exists(out));
        if (!root) {
            assertEquals(List.of(), listing(folder));
        }
    }

    @Test
    void aNewFileAndAnExistingRegularFileAreWritten() throws IOException {
        Path out = dir.resolve("new.png");
        assertEquals(0, run("render", "scenes/sphere.json", "-o", out.toString(), "-q").status());
        assertTrue(Files.size(out) > 100);
        Files.writeString(out, "old");
        assertEquals(0, run("render", "scenes/sphere.json", "-o", out.toString(), "-q").status());
        assertTrue(Files.size(out) > 100, "replaced by the new picture");
        assertEquals(List.of("new.png"), listing(dir), "no temporary or probe file left");
    }

    @Test
    void anOptionValueWithALineBreakGivesOneLine() {
        Run r = run("render", "scenes/sphere.json", "--threads", "1\n2");
        assertEquals(2, r.status(), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("1\\n2"), r.err());
    }

    @Test
    void gradingAMissingSubmissionIsBadInputAndWritesNothing() throws IOException {
        Path missing = dir.resolve("nothing.zip");
        Path out = dir.resolve("results");
        Run r = run("grade", missing.toString(), "--out", out.toString());
        assertEquals(2, r.status(), r.err());
        assertEquals("raylab: " + missing + ": no such file or directory (the submission to grade)", r.err().strip());
        assertEquals(List.of(), listing(dir), "no results folder");
    }

    @Test
    void theMemoryCheckComparesTheImageWithTheHeap() {
        assertEquals(28L * 16384 * 16384 + (64L << 20), Image.bytesNeeded(16384, 16384));
        assertNull(Image.memoryProblem(1280, 720, 512L << 20));
        assertEquals("a 16384x16384 image needs about 7.1 GiB of memory, but Java may use only 3.0 GiB more;"
                + " render a smaller image or give Java more memory, for example RAYLAB_JAVA_OPTS=-Xmx9g",
                Image.memoryProblem(16384, 16384, 3L << 30));
    }

    @Test
    void theLargestDocumentedImageIsOneLineWhenTheHeapIsTooSmall() throws Exception {
        Path scene = dir.resolve("huge.json");
        Files.writeString(scene, Files.readString(Path.of("scenes/sphere.json"))
                .replaceFirst("\"width\": *\\d+", "\"width\": 16384").replaceFirst("\"height\": *\\d+", "\"height\": 16384"));
        Path png = dir.resolve("huge.png");
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        Process p = ChildJvm.start(List.of("-Xmx256m"), Map.of(), out, err, "render", scene.toString(), "-o",
                png.toString());
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        String e = Files.readString(err, StandardCharsets.UTF_8).strip();
        assertEquals(2, p.exitValue(), e);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("raylab: " + scene + ": a 16384x16384 image needs about 7.1 GiB of memory, but"
                + " Java may use only "), e);
        assertFalse(Files.readString(out).contains("plan:"));
        assertEquals(List.of("huge.json", "stderr.txt", "stdout.txt"), listing(dir));
    }

    @Test
    void aNonAsciiMeshNameUnderThePosixLocaleIsAUserError() throws Exception {
        Path scene = dir.resolve("mesh.json");
        Files.writeString(scene, Files.readString(Path.of("scenes/mesh.json"), StandardCharsets.UTF_8)
                .replace("meshes/bunny.obj", "b\u00fcnny.obj"), StandardCharsets.UTF_8);
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        Process p = ChildJvm.start(List.of(), Map.of("LANG", "C", "LC_ALL", "C"), out, err, "render",
                scene.toString(), "-o", dir.resolve("m.png").toString());
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        String e = Files.readString(err, StandardCharsets.ISO_8859_1).strip();
        assertEquals(2, p.exitValue(), e);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("raylab: " + scene + ":"), e);
        assertTrue(e.contains("$.surfaces[0].file: cannot use \"b") && e.contains("file-name encoding"), e);
        assertFalse(e.contains("internal error"), e);
    }

    @Test
    void aNonAsciiSceneNameUnderThePosixLocaleIsOneLine() throws Exception {
        Path out = dir.resolve("stdout.txt");
        Path err = dir.resolve("stderr.txt");
        Process p = ChildJvm.start(List.of(), Map.of("LANG", "C", "LC_ALL", "C"), out, err, "render",
                "szene-\u00fc.json", "-o", dir.resolve("s.png").toString());
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        String e = Files.readString(err, StandardCharsets.ISO_8859_1).strip();
        assertEquals(2, p.exitValue(), e);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("raylab: szene-") && (e.contains("not a usable file name")
                || e.contains("no such file")), e); // "no such file" where the JVM maps the name
        assertFalse(e.contains("Exception"), e);
    }
}
