package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.camera.Camera;

/**
 * Scene files the way careless or hostile users give them: with a byte-order mark, as a pipe or a
 * device, huge, with enormous numbers or vectors, with control characters in names. Each is
 * either read correctly or refused with one line naming the file.
 */
class SceneInputTest {
    @TempDir
    Path dir;

    static final String SPHERE = """
            {
              "image": {"width": 64, "height": 48},
              "camera": {"type": "perspective", "eye": [0, 0, 5], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
              "materials": {"red": {"type": "lambertian", "kd": [0.8, 0.1, 0.1]}},
              "surfaces": [%s],
              "lights": [{"type": "point", "position": [5, 5, 5], "intensity": [1, 1, 1]}]
            }
            """;

    static String scene(String surfaces) {
        return String.format(SPHERE, surfaces);
    }

    static final String BALL = "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"red\"}";

    private SceneException refused(Path file) {
        SceneException e = assertTimeoutPreemptively(Duration.ofSeconds(60),
                () -> assertThrows(SceneException.class, () -> SceneLoader.load(file)),
                "refused without waiting for the file to end");
        assertTrue(e.getMessage().startsWith(file.toString()), e.getMessage());
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
        return e;
    }

    @Test
    void aUtf8ByteOrderMarkIsAccepted() throws Exception {
        Path plain = dir.resolve("plain.json");
        Path bom = dir.resolve("bom.json");
        Files.writeString(plain, scene(BALL), StandardCharsets.UTF_8);
        byte[] text = scene(BALL).getBytes(StandardCharsets.UTF_8);
        byte[] withBom = new byte[text.length + 3];
        withBom[0] = (byte) 0xEF;
        withBom[1] = (byte) 0xBB;
        withBom[2] = (byte) 0xBF;
        System.arraycopy(text, 0, withBom, 3, text.length);
        Files.write(bom, withBom);
        Scene a = SceneLoader.load(plain);
        Scene b = SceneLoader.load(bom);
        assertEquals(a.width, b.width);
        assertEquals(a.surfaces.size(), b.surfaces.size());
        assertEquals(a.camera.w, b.camera.w);
        assertEquals(1, SceneLoader.parse("\uFEFF" + scene(BALL), bom).surfaces.size());
    }

    @Test
    void aByteOrderMarkInsideTheTextIsNamedAtItsPlace() {
        Path f = dir.resolve("mid.json");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.parse("\n\uFEFF{}", f));
        assertEquals(f + ":2:1: $: a byte-order mark (U+FEFF) in the middle of the text; it may only stand"
                + " at the very start of the file", e.getMessage());
    }

    @Test
    void aNamedPipeIsRefusedBeforeReading() throws Exception {
        Path fifo = dir.resolve("pipe.json");
        assumeTrue(mkfifo(fifo), "mkfifo is not available");
        assertEquals(fifo + ": is a named pipe (FIFO), not a regular file; a scene file must be a regular file",
                refused(fifo).getMessage());
    }

    @Test
    void aDeviceIsRefusedBeforeReading() {
        Path zero = Path.of("/dev/zero");
        assumeTrue(Files.exists(zero), "no /dev/zero here");
        assertEquals("/dev/zero: is a character device, not a regular file; a scene file must be a regular file",
                refused(zero).getMessage());
    }

    @Test
    void aMeshThatIsANamedPipeIsRefusedBeforeReading() throws Exception {
        Path fifo = dir.resolve("pipe.obj");
        assumeTrue(mkfifo(fifo), "mkfifo is not available");
        Path scene = dir.resolve("mesh.json");
        Files.writeString(scene, scene("{\"type\": \"mesh\", \"file\": \"pipe.obj\", \"material\": \"red\"}"));
        assertEquals(scene + ":5:41: $.surfaces[0].file: " + fifo + ": is a named pipe (FIFO), not a regular"
                + " file; an OBJ file must be a regular file", refused(scene).getMessage());
    }

    @Test
    void aFileLargerThanTheCapIsRefusedUnread() throws IOException {
        Path big = dir.resolve("big.json");
        try (RandomAccessFile f = new RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(SceneLoader.MAX_SCENE_BYTES + 1); // sparse: no disk space used
        }
        assertEquals(big + ": larger than 64 MiB; a scene file is a small JSON text (put large meshes in OBJ"
                + " files)", refused(big).getMessage());
    }

    @Test
    void aNumberLongerThanTheLimitIsReportedAtItsOwnPlace() {
        String digits = "7".repeat(JsonTree.MAX_NUMBER_LENGTH + 5);
        String json = scene(BALL).replace("\"fov\": 40", "\"fov\":\n   " + digits);
        Path f = dir.resolve("long.json");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.parse(json, f));
        assertEquals(f + ":4:4: $.camera.fov: a number with more than 100000 characters", e.getMessage());
    }

    @Test
    void aLongFractionIsJustAFraction() throws SceneException {
        String json = scene(BALL.replace("\"radius\": 1", "\"radius\": 0." + "5".repeat(1500)));
        Scene s = SceneLoader.parse(json, dir.resolve("fraction.json"));
        assertEquals(1, s.surfaces.size());
    }

    @Test
    void controlCharactersInNamesAreKeptEscaped() throws SceneException {
        String json = scene(BALL.replace("{\"type\"", "{\"name\": \"two\\nlines\\u2028\\u0007\", \"type\""));
        Scene s = SceneLoader.parse(json, dir.resolve("names.json"));
        assertEquals("two\\nlines\\u2028\\u0007", s.surfaces.get(0).name());
    }

    @Test
    void aFileNameWithALineBreakIsEscapedInMessages() {
        Path f = dir.resolve("two\nlines.json");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(f));
        assertEquals(Display.path(dir) + "/two\\nlines.json: no such file", e.getMessage());
    }

    @Test
    void hugeViewAndUpVectorsGiveTheSameCameraAsSmallOnes() throws SceneException {
        String small = scene(BALL).replace("\"lookAt\": [0, 0, 0], \"up\": [0, 1, 0]",
                "\"viewDirection\": [1, 0, -1], \"up\": [0, 1, 0.5]");
        // The same directions times 2^900: their squared lengths overflow to infinity.
        String big = Double.toString(Math.scalb(1.0, 900));
        String half = Double.toString(Math.scalb(1.0, 899));
        String huge = scene(BALL).replace("\"lookAt\": [0, 0, 0], \"up\": [0, 1, 0]",
                "\"viewDirection\": [" + big + ", 0, -" + big + "], \"up\": [0, " + big + ", " + half + "]");
        Camera a = SceneLoader.parse(small, dir.resolve("a.json")).camera;
        Camera b = SceneLoader.parse(huge, dir.resolve("b.json")).camera;
        assertEquals(a.u, b.u);
        assertEquals(a.v, b.v);
        assertEquals(a.w, b.w);
        assertTrue(b.w.isFinite() && Math.abs(b.w.length() - 1) < 1e-15, "w is a unit vector: " + b.w);
    }

    @Test
    void displayEscapesWhatCouldBreakOrHideALine() {
        assertEquals("a\\nb\\rc\\td\\u0000e\\u007f\\u0085\\u2028\\u202e\\ud800", Display.escape(
                "a\nb\rc\td\u0000e\u007f\u0085\u2028\u202e\ud800"));
        assertEquals("bünny 🐇.obj", Display.escape("bünny 🐇.obj"), "printable text and pairs are kept");
        String once = Display.escape("x\ny");
        assertEquals(once, Display.escape(once), "escaping is idempotent");
    }

    static boolean mkfifo(Path p) throws InterruptedException {
        try {
            return new ProcessBuilder("mkfifo", p.toString()).inheritIO().start().waitFor() == 0;
        } catch (IOException e) {
            return false;
        }
    }
}
