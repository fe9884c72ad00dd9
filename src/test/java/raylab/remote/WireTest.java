package raylab.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
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
}
