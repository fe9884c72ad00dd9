package raylab.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.util.List;

import org.junit.jupiter.api.Test;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** The frame and value encoding alone, in one process. */
class WireTest {
    static final double[] SPECIAL = {0.0, -0.0, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN,
        Double.longBitsToDouble(0x7ff8_0000_0000_0123L), Double.longBitsToDouble(0xfff0_0000_0000_0001L),
        Double.MIN_VALUE, -Double.MIN_VALUE, Double.MAX_VALUE, Math.nextDown(1.0), 1e-300, 0.1};

    static Object roundTrip(Object v) throws IOException {
        Wire.Out o = new Wire.Out();
        Wire.writeValue(o, v, null);
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        Wire.writeFrame(b, Wire.CALL, 42, o);
        Wire.Frame f = Wire.readFrame(new DataInputStream(new ByteArrayInputStream(b.toByteArray())));
        assertEquals(Wire.CALL, f.type());
        assertEquals(42, f.conv());
        Object back = Wire.readValue(f.in(), null);
        assertTrue(f.in().atEnd(), "the whole frame was read");
        return back;
    }

    static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    @Test
    void doublesArriveBitForBit() throws IOException {
        for (double d : SPECIAL) {
            Object back = roundTrip(d);
            assertEquals(bits(d), bits((Double) back), () -> "bits of " + d + " (raw " + Long.toHexString(bits(d)) + ")");
            Vec3 v = (Vec3) roundTrip(new Vec3(d, -d, 1 / d));
            assertEquals(bits(d), bits(v.x), "Vec3.x");
            assertEquals(bits(-d), bits(v.y), "Vec3.y");
            assertEquals(bits(1 / d), bits(v.z), "Vec3.z");
        }
    }

    @Test
    void everyTagRoundTrips() throws IOException {
        assertEquals(null, roundTrip(null));
        assertEquals(Boolean.TRUE, roundTrip(true));
        assertEquals(Boolean.FALSE, roundTrip(false));
        assertEquals(-17, roundTrip(-17));
        assertEquals(Long.MIN_VALUE, roundTrip(Long.MIN_VALUE));
        assertEquals("π ≈ 3.14 \u0000 end", roundTrip("π ≈ 3.14 \u0000 end"));
        Color c = (Color) roundTrip(new Color(-0.0, Double.NaN, 0.25));
        assertEquals(bits(-0.0), bits(c.r));
        assertEquals(bits(Double.NaN), bits(c.g));
        assertEquals(0.25, c.b);
        Ray r = (Ray) roundTrip(new Ray(new Vec3(1, 2, 3), new Vec3(0, 0, -1), Double.MIN_VALUE, Math.nextDown(1.0)));
        assertEquals(new Vec3(1, 2, 3).toString(), r.p.toString());
        assertEquals(bits(Double.MIN_VALUE), bits(r.tMin));
        assertEquals(bits(Math.nextDown(1.0)), bits(r.tMax));
        PointLight l = (PointLight) roundTrip(new PointLight(new Vec3(0, 5, 0), new Color(1, 0.5, 0), false, "lamp"));
        assertEquals("lamp", l.name);
        assertEquals(false, l.castsShadows);
        assertEquals(0.5, l.intensity.g);
        IntersectionRecord rec = new IntersectionRecord();
        rec.t = 2.5;
        rec.point = new Vec3(1, 1, 1);
        rec.normal = new Vec3(0, -0.0, 1);
        rec.primitive = 12;
        rec.tests = 99;
        IntersectionRecord back = (IntersectionRecord) roundTrip(rec);
        assertEquals(2.5, back.t);
        assertEquals(bits(-0.0), bits(back.normal.y));
        assertEquals(12, back.primitive);
        assertEquals(99, back.tests);
        assertEquals(null, back.surface);
        IntersectionRecord empty = (IntersectionRecord) roundTrip(new IntersectionRecord());
        assertEquals(Double.POSITIVE_INFINITY, empty.t);
        assertEquals(null, empty.point);
        assertEquals(List.of(1, "two", 3.0), roundTrip(List.of(1, "two", 3.0)));
    }

    @Test
    void brokenFramesAreProtocolErrors() {
        byte[] tooLong = {0x7f, 0, 0, 0, Wire.CALL, 0, 0, 0, 1};
        assertThrows(Wire.ProtocolException.class,
                () -> Wire.readFrame(new DataInputStream(new ByteArrayInputStream(tooLong))));
        byte[] cut = {0, 0, 0, 20, Wire.CALL, 0, 0, 0, 1, 5};
        assertThrows(Wire.ProtocolException.class,
                () -> Wire.readFrame(new DataInputStream(new ByteArrayInputStream(cut))));
        Wire.In unknownTag = new Wire.In(new byte[] {99}, 0, 1);
        assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(unknownTag, null));
        Wire.In shortInt = new Wire.In(new byte[] {Wire.INT, 0, 1}, 0, 3);
        assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(shortInt, null));
    }

    /** Bytes allocated by this thread while {@code r} runs (HotSpot's per-thread counter). */
    static long allocatedBy(ThrowingRunnable r) throws Exception {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long before = mx.getThreadAllocatedBytes(id);
        r.run();
        return mx.getThreadAllocatedBytes(id) - before;
    }

    interface ThrowingRunnable {
        void run() throws Exception;
    }

    static Wire.In payload(byte[] b) {
        return new Wire.In(b, 0, b.length);
    }

    /** {@code depth} lists, each holding the next, the innermost holding null. */
    static byte[] nestedLists(int depth) {
        ByteBuffer b = ByteBuffer.allocate(5 * depth + 1);
        for (int i = 0; i < depth; i++) {
            b.put(Wire.LIST).putInt(1);
        }
        b.put(Wire.NULL);
        return b.array();
    }

    @Test
    void nestingIsBoundedAndSaysSo() throws IOException {
        // MAX_DEPTH values, one inside the other: MAX_DEPTH - 1 lists and the null in the innermost.
        Object v = Wire.readValue(payload(nestedLists(Wire.MAX_DEPTH - 1)), null);
        for (int i = 2; i < Wire.MAX_DEPTH; i++) {
            v = ((List<?>) v).get(0);
        }
        assertEquals(java.util.Collections.singletonList(null), v, "the innermost of " + (Wire.MAX_DEPTH - 1) + " lists");
        assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(payload(nestedLists(Wire.MAX_DEPTH)), null));
        Wire.ProtocolException e = assertThrows(Wire.ProtocolException.class,
                () -> Wire.readValue(payload(nestedLists(1_500_000)), null));
        assertEquals("values nested more than " + Wire.MAX_DEPTH + " deep", e.getMessage());
        // A light's colour that is a light, a record's surface that is a record: nesting too.
        ByteBuffer lights = ByteBuffer.allocate(2 * 100_000);
        for (int i = 0; i < 100_000; i++) {
            lights.put(Wire.LIGHT).put(Wire.NULL);
        }
        e = assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(payload(lights.array()), null));
        assertEquals("values nested more than " + Wire.MAX_DEPTH + " deep", e.getMessage());
        ByteBuffer records = ByteBuffer.allocate(11 * 100_000);
        for (int i = 0; i < 100_000; i++) {
            records.put(Wire.RECORD).putDouble(1).put(Wire.NULL).put(Wire.NULL);
        }
        e = assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(payload(records.array()), null));
        assertEquals("values nested more than " + Wire.MAX_DEPTH + " deep", e.getMessage());
    }

    @Test
    void listsThatDeclareTheWholeFrameAllocateOnlyWhatIsRead() throws Exception {
        // 24 MB of lists inside lists, each declaring nearly all of it (the attack of issue 35):
        // ahead-sized lists took 96 MB per level.
        int size = 24 << 20;
        ByteBuffer b = ByteBuffer.allocate(size);
        for (int i = 0; i < 1000; i++) {
            b.put(Wire.LIST).putInt(size - 2000);
        }
        byte[] bytes = b.array();
        long allocated = allocatedBy(() -> assertThrows(Wire.ProtocolException.class,
                () -> Wire.readValue(payload(bytes), null)));
        assertTrue(allocated < (1 << 20), "reading 32 nested lists that each declare " + (size - 2000)
                + " elements allocated " + allocated + " bytes; expected under 1 MiB");
        Wire.ProtocolException e = assertThrows(Wire.ProtocolException.class,
                () -> Wire.readValue(payload(new byte[] {Wire.LIST, 0, 0, 0, 9, Wire.NULL}), null));
        assertEquals("bad list length 9 (1 bytes left)", e.getMessage());
    }

    @Test
    void aFrameDeclaredLargeAllocatesWhatArrives() throws Exception {
        ByteBuffer head = ByteBuffer.allocate(9 + 20).putInt(Wire.MAX_FRAME).put(Wire.RETURN).putInt(1);
        byte[] bytes = head.array();
        Wire.ProtocolException e = assertThrows(Wire.ProtocolException.class,
                () -> Wire.readFrame(new DataInputStream(new ByteArrayInputStream(bytes))));
        assertEquals("frame cut short (" + Wire.MAX_FRAME + " bytes declared)", e.getMessage());
        long measured = allocatedBy(() -> assertThrows(Wire.ProtocolException.class,
                () -> Wire.readFrame(new DataInputStream(new ByteArrayInputStream(bytes)))));
        assertTrue(measured < (1 << 20), "a frame declaring " + Wire.MAX_FRAME + " bytes with 20 sent allocated "
                + measured + " bytes; expected under 1 MiB");
        // A frame that does arrive whole is read whole, in pieces.
        Wire.Out o = new Wire.Out();
        Wire.writeValue(o, "x".repeat(3 << 20), null);
        ByteArrayOutputStream w = new ByteArrayOutputStream();
        Wire.writeFrame(w, Wire.RETURN, 5, o);
        Wire.Frame f = Wire.readFrame(new DataInputStream(new ByteArrayInputStream(w.toByteArray())));
        assertEquals(3 << 20, ((String) Wire.readValue(f.in(), null)).length());
    }

    @Test
    void aSizePastTheEndIsRefusedWithoutOverflow() {
        byte[] b = ByteBuffer.allocate(12).put(Wire.INT).putInt(1).put(Wire.STRING).putInt(Integer.MAX_VALUE)
                .put((byte) 'a').put((byte) 'b').array();
        Wire.In in = payload(b);
        Wire.ProtocolException e = assertThrows(Wire.ProtocolException.class, () -> {
            Wire.readValue(in, null);
            Wire.readValue(in, null);
        });
        assertEquals("frame too short (" + Integer.MAX_VALUE + " bytes wanted, 2 left)", e.getMessage());
    }

    @Test
    void aFrameHoldsAtMostMaxValues() throws IOException {
        byte[] nulls = new byte[Wire.MAX_VALUES + 1];
        Wire.In in = payload(nulls);
        for (int i = 0; i < Wire.MAX_VALUES; i++) {
            Wire.readValue(in, null);
        }
        Wire.ProtocolException e = assertThrows(Wire.ProtocolException.class, () -> Wire.readValue(in, null));
        assertEquals("more than " + Wire.MAX_VALUES + " values in one frame", e.getMessage());
    }

    /** What each saved input of WireFuzzTest is, and that the reader refuses it as it should. */
    @Test
    void theFuzzersSavedInputsAreRefusedForWhatTheyAre() throws Exception {
        java.nio.file.Path dir = java.nio.file.Path.of("src/test/resources/raylab/remote/WireFuzzTestInputs/frames");
        String deep = "values nested more than " + Wire.MAX_DEPTH + " deep";
        java.util.Map<String, String> expected = new java.util.TreeMap<>(java.util.Map.of(
                "nested-24mb", deep, "deep-lists", deep, "deep-lights", deep, "deep-records", deep,
                "declared-64mb", "frame cut short (" + Wire.MAX_FRAME + " bytes declared)",
                "over-max", "bad frame length " + (Wire.MAX_FRAME + 1),
                "string-overflow", "frame too short (" + Integer.MAX_VALUE + " bytes wanted, 3 left)",
                "well-formed", "(read whole)"));
        java.util.Map<String, String> got = new java.util.TreeMap<>();
        try (var files = java.nio.file.Files.list(dir)) {
            for (java.nio.file.Path f : (Iterable<java.nio.file.Path>) files::iterator) {
                String said = "(read whole)";
                try {
                    WireFuzzTest.readAll(WireFuzzTest.expand(java.nio.file.Files.readAllBytes(f)));
                } catch (Wire.ProtocolException e) {
                    said = e.getMessage();
                }
                got.put(f.getFileName().toString(), said);
            }
        }
        assertEquals(expected, got);
    }
}
