package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import raylab.math.Vec3;

class ObjLoaderTest {
    private static final Vec3 A = new Vec3(0, 0, 0);
    private static final Vec3 B = new Vec3(1, 0, 0);
    private static final Vec3 C = new Vec3(1, 1, 0);
    private static final Vec3 D = new Vec3(0, 1, 0);
    private static final Vec3 E = new Vec3(0.5, 2, 0);
    private static final String PENTAGON_VERTICES = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\n";

    private static String message(String obj) {
        return assertThrows(ObjLoader.ObjException.class, () -> ObjLoader.parse(obj, "m.obj"),
                () -> "should fail: " + obj.replace("\n", "\\n")).getMessage();
    }

    @Test
    void pentagonIsFannedAroundItsFirstVertex() throws Exception {
        List<Vec3[]> t = ObjLoader.parse(PENTAGON_VERTICES + "f 1 2 3 4 5\n", "m.obj");
        assertEquals(3, t.size());
        assertArrayEquals(new Vec3[] {A, B, C}, t.get(0));
        assertArrayEquals(new Vec3[] {A, C, D}, t.get(1));
        assertArrayEquals(new Vec3[] {A, D, E}, t.get(2));
    }

    @ParameterizedTest(name = "face \"{0}\"")
    @CsvSource(delimiter = ';', value = {
        "f 2 3 4", "f 2/1 3/2 4/3", "f 2//1 3//1 4//1", "f 2/1/1 3/2/1 4/3/1",
        "f -4 -3 -2", "f -4/1/1 3//1 -2/7", "f\t2   3 \t4  # comment"})
    void faceVertexFormsAndNegativeIndicesPickTheSameVertices(String face) throws Exception {
        List<Vec3[]> t = ObjLoader.parse(PENTAGON_VERTICES + face + "\n", "m.obj");
        assertEquals(1, t.size(), face);
        assertArrayEquals(new Vec3[] {B, C, D}, t.get(0), face);
    }

    @Test
    void otherStatementsCommentsWAndLineEndingsAreIgnored() throws Exception {
        String obj = "# header\r\nmtllib x.mtl\r\no thing\r\ng group\r\ns 1\r\nusemtl red\r\n"
                + "v 0 0 0 1\rv 1 0 0\r\nvt 0 0\nvn 0 0 1\nvp 0.5\nl 1 2\nfoo bar\n\n"
                + "v 0 1 0 1.0 0.5 0.5 0.5\nf 1 2 3\n";
        List<Vec3[]> t = ObjLoader.parse(obj, "m.obj");
        assertEquals(1, t.size());
        assertArrayEquals(new Vec3[] {A, B, D}, t.get(0));
    }

    @Test
    void negativeIndicesCountFromTheLastVertexDefinedSoFar() throws Exception {
        List<Vec3[]> t = ObjLoader.parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2 -1\n",
                "m.obj");
        assertArrayEquals(new Vec3[] {A, B, C}, t.get(0));
        assertArrayEquals(new Vec3[] {A, C, D}, t.get(1));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "index 0           | f 0 1 2                | m.obj:4: vertex index 0 is invalid (OBJ indices start at 1)",
        "index too large   | f 1 2 4                | m.obj:4: vertex index 4 is out of range: only 3 vertices are defined before this line",
        "relative too far  | f -1 -2 -4             | m.obj:4: relative vertex index -4 is out of range: only 3 vertices are defined before this line",
        "huge index        | f 1 2 99999999999999999999 | m.obj:4: vertex index 99999999999999999999 is out of range: only 3 vertices are defined before this line",
        "two vertices      | f 1 2                  | m.obj:4: a face needs at least 3 vertices, got 2",
        "malformed vertex  | f 1/2/3/4 2 3          | m.obj:4: malformed face vertex '1/2/3/4' (expected i, i/t, i//n or i/t/n with integer indices)",
        "word as index     | f a b c                | m.obj:4: malformed face vertex 'a' (expected i, i/t, i//n or i/t/n with integer indices)",
        "bad coordinate    | v 1 2 x                | m.obj:4: expected a number, got 'x'",
        "nan coordinate    | v 1 NaN 2              | m.obj:4: expected a number, got 'NaN'",
        "overflow          | v 1 1e999 2            | m.obj:4: the number 1e999 is too large (it overflows to infinity)",
        "short vertex      | v 1 2                  | m.obj:4: a vertex needs 3 coordinates (v x y z), got 2",
    })
    void errorsNameTheFileAndLine(String what, String line4, String expected) {
        assertEquals(expected, message("v 0 0 0\nv 1 0 0\nv 0 1 0\n" + line4 + "\nf 1 2 3\n"), what);
    }

    @Test
    void aFileWithoutFacesIsAnError() {
        assertEquals("m.obj: no faces (a mesh needs at least one 'f' line)",
                message("v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
        assertEquals("m.obj: no faces (a mesh needs at least one 'f' line)", message(""));
    }

    @Test
    void missingAndBinaryFiles(@TempDir Path tmp) throws Exception {
        Path missing = tmp.resolve("none.obj");
        assertEquals("none.obj: no such file", assertThrows(ObjLoader.ObjException.class,
                () -> ObjLoader.readTriangles(missing, "none.obj")).getMessage());
        Path bin = tmp.resolve("bin.obj");
        Files.write(bin, new byte[] {'v', ' ', '1', 0, 0, 1});
        assertEquals("bin.obj: not a text file (NUL byte at offset 3); an OBJ file is text",
                assertThrows(ObjLoader.ObjException.class,
                        () -> ObjLoader.readTriangles(bin, "bin.obj")).getMessage());
    }

    @Test
    void aUtf8ByteOrderMarkIsSkipped(@TempDir Path tmp) throws Exception {
        Path f = tmp.resolve("bom.obj");
        byte[] text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        byte[] withBom = new byte[text.length + 3];
        withBom[0] = (byte) 0xEF;
        withBom[1] = (byte) 0xBB;
        withBom[2] = (byte) 0xBF;
        System.arraycopy(text, 0, withBom, 3, text.length);
        Files.write(f, withBom);
        List<Vec3[]> t = ObjLoader.readTriangles(f, "bom.obj");
        assertArrayEquals(new Vec3[] {A, B, C}, t.get(0));
    }

    @Test
    void devicesAndFifosAreRefusedBeforeReading(@TempDir Path tmp) throws Exception {
        Path zero = Path.of("/dev/zero");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(zero), "no /dev/zero here");
        String expected = "zero.obj: not a regular file (a device, FIFO or socket); an OBJ file must be a regular file";
        assertEquals(expected, assertThrows(ObjLoader.ObjException.class,
                () -> ObjLoader.readTriangles(zero, "zero.obj")).getMessage());
        Path fifo = tmp.resolve("pipe.obj");
        Process p = new ProcessBuilder("mkfifo", fifo.toString()).redirectErrorStream(true).start();
        org.junit.jupiter.api.Assumptions.assumeTrue(p.waitFor() == 0 && Files.exists(fifo), "no mkfifo here");
        // Opening a FIFO with no writer would block forever: the check must come first.
        assertEquals(expected.replace("zero.obj", "pipe.obj"), assertThrows(ObjLoader.ObjException.class,
                () -> ObjLoader.readTriangles(fifo, "pipe.obj")).getMessage());
    }

    @Test
    void filesLargerThanTheCapAreRefused(@TempDir Path tmp) throws Exception {
        Path f = tmp.resolve("big.obj");
        Files.writeString(f, "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
        assertEquals("big.obj: too large (32 bytes; the limit is 20 bytes, set by -Draylab.obj.maxBytes)",
                assertThrows(ObjLoader.ObjException.class, () -> ObjLoader.readBytes(f, "big.obj", 20)).getMessage());
        assertEquals(32, ObjLoader.readBytes(f, "big.obj", 32).length, "exactly at the cap is fine");
    }

    /** Random numbers in every form the grammar allows, some beyond the fast path. */
    static String randomNumber(java.util.SplittableRandom r) {
        StringBuilder s = new StringBuilder();
        switch (r.nextInt(3)) {
            case 0 -> s.append('-');
            case 1 -> s.append(r.nextInt(4) == 0 ? "+" : "");
            default -> { }
        }
        int intDigits = r.nextInt(4) == 0 ? 0 : 1 + r.nextInt(r.nextInt(5) == 0 ? 22 : 8);
        int fracDigits = r.nextInt(4) == 0 ? 0 : 1 + r.nextInt(r.nextInt(5) == 0 ? 22 : 9);
        if (intDigits == 0 && fracDigits == 0) {
            intDigits = 1;
        }
        for (int i = 0; i < intDigits; i++) {
            s.append((char) ('0' + r.nextInt(10)));
        }
        if (fracDigits > 0 || r.nextInt(8) == 0) {
            s.append('.');
        }
        for (int i = 0; i < fracDigits; i++) {
            s.append((char) ('0' + (r.nextInt(3) == 0 ? 0 : r.nextInt(10))));
        }
        if (r.nextInt(3) == 0) {
            s.append(r.nextBoolean() ? 'e' : 'E');
            s.append(r.nextInt(3) == 0 ? "-" : r.nextInt(2) == 0 ? "+" : "");
            s.append(r.nextInt(r.nextInt(4) == 0 ? 330 : 30));
        }
        return s.toString();
    }

    @ParameterizedTest(name = "seed {0}")
    @org.junit.jupiter.params.provider.ValueSource(longs = {1, 2, 3, 4, 5})
    void coordinatesAreParsedExactlyAsDoubleParseDouble(long seed) throws Exception {
        java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
        StringBuilder obj = new StringBuilder();
        List<String> numbers = new java.util.ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            String x = randomNumber(r);
            if (!Double.isFinite(Double.parseDouble(x))) {
                continue;
            }
            numbers.add(x);
        }
        while (numbers.size() % 3 != 0) {
            numbers.remove(numbers.size() - 1);
        }
        for (int i = 0; i < numbers.size(); i += 3) {
            obj.append("v ").append(numbers.get(i)).append(' ').append(numbers.get(i + 1)).append(' ')
                    .append(numbers.get(i + 2)).append('\n');
        }
        obj.append("f 1 2 3\n");
        ObjLoader.Indexed m = ObjLoader.parse(obj.toString().getBytes(java.nio.charset.StandardCharsets.US_ASCII), "n.obj");
        for (int i = 0; i < numbers.size(); i++) {
            double want = Double.parseDouble(numbers.get(i));
            assertEquals(Double.doubleToRawLongBits(want), Double.doubleToRawLongBits(m.vertices()[i]),
                    "seed " + seed + ": '" + numbers.get(i) + "' read as " + m.vertices()[i] + ", not " + want);
        }
    }

    @Test
    void facesAreStoredAsIndicesIntoTheVertices() throws Exception {
        ObjLoader.Indexed m = ObjLoader.parse((PENTAGON_VERTICES + "f 1 2 3 4 5\nf -1 -2 -3\n")
                .getBytes(java.nio.charset.StandardCharsets.US_ASCII), "m.obj");
        assertEquals(4, m.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 0, 3, 4, 4, 3, 2}, m.indices());
        double[] v = m.triangleVertices();
        assertEquals(36, v.length);
        assertEquals(0.5, v[27]); // fourth triangle's first vertex is E = (0.5, 2, 0)
        assertEquals(2.0, v[28]);
    }
}
