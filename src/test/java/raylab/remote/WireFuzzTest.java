package raylab.remote;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.code_intelligence.jazzer.junit.FuzzTest;

import raylab.fuzzing.OneLine;
import raylab.light.PointLight;
import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.surface.Sphere;

/**
 * Fuzzes the trusted side's frame reader ({@link Wire#readFrame}, {@link Wire#readValue},
 * {@link Wire#readRecordInto}) on what a hostile student process may send: the input, expanded by
 * {@link #expand}, is a stream of frames; each frame's payload is read as the trusted side reads
 * it (a CALLBACK's object, operation and arguments; a RETURN's result and records; values until
 * the end otherwise), with references resolved as {@code StudentProcess} resolves them. The
 * property: every frame is read or refused with a {@link Wire.ProtocolException} whose message is
 * one line; never another exception, an {@link OutOfMemoryError} or a {@link StackOverflowError}.
 * Saved inputs: src/test/resources/raylab/remote/WireFuzzTestInputs/frames, among them a 24 MB
 * callback of lists inside lists that each declare nearly the whole frame ({@code nested-24mb}),
 * lists, lights and records nested 1.5 million deep ({@code deep-*}), and frames that declare
 * 64 MB and bring 20 bytes ({@code declared-64mb}).
 */
class WireFuzzTest {
    /** The most bytes an input expands to: one frame of the largest size and a little more. */
    static final int EXPANDED_CAP = Wire.MAX_FRAME + 64;

    /** What the trusted side's references resolve to: two handles, three ephemeral objects. */
    static final class TrustedRefs implements Wire.Refs {
        final FlatColor material = new FlatColor(new Color(1, 0, 0), "red");
        final Sphere sphere = new Sphere(new Vec3(0, 0, 0), 1, material, "ball");
        final List<Object> handles = List.of(sphere, new Sphere(new Vec3(1, 0, 0), 2, material, "other"));
        final List<Object> ephemeral = List.of(sphere, material,
                new PointLight(new Vec3(0, 5, 0), new Color(1, 1, 1), true, "lamp"));

        @Override
        public boolean encode(Wire.Out out, Object o) {
            return false;
        }

        @Override
        public Object decode(byte tag, Wire.In in) throws IOException {
            int id = in.readInt();
            List<Object> table = switch (tag) {
                case Wire.HANDLE -> handles;
                case Wire.REMOTE_SURFACE, Wire.REMOTE_MATERIAL, Wire.LIGHT_REF -> ephemeral;
                default -> throw new Wire.ProtocolException("unknown value tag " + tag);
            };
            if (id < 1 || id > table.size()) {
                throw new Wire.ProtocolException("unknown object " + id);
            }
            return table.get(id - 1);
        }
    }

    @FuzzTest(maxDuration = "60s")
    void frames(byte[] data) {
        try {
            readAll(expand(data));
        } catch (Wire.ProtocolException e) {
            OneLine.check(e.getMessage(), null, false, e);
        }
    }

    /** Reads every frame of {@code stream} as the trusted side does, until its clean end. */
    static void readAll(InputStream stream) throws Wire.ProtocolException {
        TrustedRefs refs = new TrustedRefs();
        DataInputStream in = new DataInputStream(stream);
        while (true) {
            Wire.Frame f;
            try {
                f = Wire.readFrame(in);
            } catch (EOFException end) {
                return;
            } catch (Wire.ProtocolException e) {
                throw e;
            } catch (IOException e) {
                throw new AssertionError("an IOException that is not a protocol error", e);
            }
            readPayload(f, refs);
        }
    }

    private static void readPayload(Wire.Frame f, Wire.Refs refs) throws Wire.ProtocolException {
        Wire.In in = f.in();
        try {
            if (f.type() == Wire.CALLBACK) {
                in.readInt();
                in.readByte();
                int n = in.readInt();
                if (n < 0 || n > in.remaining()) {
                    throw new Wire.ProtocolException("bad callback argument count");
                }
                for (int i = 0; i < n; i++) {
                    Wire.readValue(in, refs);
                }
            } else if (f.type() == Wire.RETURN) {
                Wire.readValue(in, refs);
                while (!in.atEnd()) {
                    Wire.readRecordInto(in, new IntersectionRecord(), refs);
                }
            } else {
                while (!in.atEnd()) {
                    Wire.readValue(in, refs);
                }
            }
        } catch (Wire.ProtocolException e) {
            throw e;
        } catch (IOException e) {
            throw new AssertionError("an IOException that is not a protocol error", e);
        }
    }

    /**
     * The bytes an input stands for, so that small inputs can stand for huge frames: an input that
     * starts with {@code "RL*"} is a list of pieces {@code [byte k][k bytes][int r]}, the k bytes
     * repeated r times (big-endian r; a piece cut short is taken as far as it goes), at most
     * {@link #EXPANDED_CAP} bytes in all, produced as they are read (nothing is held but the
     * pieces); any other input is its own bytes.
     */
    static InputStream expand(byte[] data) {
        if (data.length < 3 || data[0] != 'R' || data[1] != 'L' || data[2] != '*') {
            return new ByteArrayInputStream(data);
        }
        List<byte[]> pieces = new ArrayList<>();
        List<Long> repeats = new ArrayList<>();
        int pos = 3;
        while (pos < data.length) {
            int k = data[pos++] & 0xff;
            byte[] piece = Arrays.copyOfRange(data, pos, Math.min(data.length, pos + k));
            pos += piece.length;
            long r = 1;
            if (pos + 4 <= data.length) {
                r = ((data[pos] & 0xffL) << 24) | ((data[pos + 1] & 0xffL) << 16) | ((data[pos + 2] & 0xffL) << 8)
                        | (data[pos + 3] & 0xffL);
                pos += 4;
            } else {
                pos = data.length;
            }
            if (piece.length > 0 && r > 0) {
                pieces.add(piece);
                repeats.add(r);
            }
        }
        return new InputStream() {
            int piece;
            long done;
            int at;
            long left = EXPANDED_CAP;

            @Override
            public int read() {
                byte[] one = new byte[1];
                return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                int n = 0;
                while (n < len && left > 0 && piece < pieces.size()) {
                    byte[] p = pieces.get(piece);
                    int k = (int) Math.min(Math.min(len - n, p.length - at), left);
                    System.arraycopy(p, at, b, off + n, k);
                    n += k;
                    left -= k;
                    at += k;
                    if (at == p.length) {
                        at = 0;
                        if (++done == repeats.get(piece)) {
                            done = 0;
                            piece++;
                        }
                    }
                }
                return n == 0 && len > 0 ? -1 : n;
            }
        };
    }
}
