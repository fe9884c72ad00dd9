package raylab.remote;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The binary protocol between the grader and the student process ({@link StudentServer}).
 *
 * <p>A frame is {@code [int len][byte type][int conv][payload]}, big-endian, where {@code len}
 * counts the type, the conversation number and the payload. A reply carries the number of the
 * frame it answers. Values are tagged ({@link #writeValue}); doubles travel as their raw bits, so
 * NaN payloads, −0 and the infinities arrive exactly. Nothing here is secret: the same class runs
 * on both sides.
 *
 * <p>The reader takes any bytes: a frame's length is checked against {@link #MAX_FRAME} and its
 * bytes are read as they arrive (nothing is allocated for bytes that never come); every size inside
 * a frame is checked against the bytes left in it before anything is allocated; values nest at most
 * {@link #MAX_DEPTH} deep and a frame holds at most {@link #MAX_VALUES} of them. Whatever is wrong
 * with a frame ends in a {@link ProtocolException} (fuzzed: {@code WireFuzzTest}).
 *
 * <p>One protocol kept whole on purpose: each encoder sits beside its decoder, and both sides run this
 * same class.
 */
public final class Wire {
    /** The first line the student process prints, before any frame. */
    public static final String HELLO = "raylab-student-server 1";
    /** The largest frame either side accepts (a frame over it is a protocol error). */
    public static final int MAX_FRAME = 64 << 20;
    /** The deepest nesting of values (a list in a list, a light's colour, a record's surface...). */
    public static final int MAX_DEPTH = 32;
    /** The most values one frame may hold (with {@link #MAX_FRAME}, what reading a frame may allocate). */
    public static final int MAX_VALUES = 1 << 21;
    /** A frame's bytes are read in pieces of at most this, the buffer growing as they arrive. */
    private static final int READ_PIECE = 1 << 16;

    // Frame types.
    /** Grader: {@code [int handle][String class][values...]} construct a student object. */
    public static final byte DEFINE = 1;
    /** Grader: {@code [int id][String class][String name][int arity]} name a method for CALL. */
    public static final byte METHOD = 2;
    /** Grader: {@code [int method][value target][int n][values]}. */
    public static final byte CALL = 3;
    /** Student: {@code [value result][records of the record arguments][String output]}. */
    public static final byte RETURN = 4;
    /** Student: {@code [String class][String message][int n][String frames][String output]}. */
    public static final byte THROW = 5;
    /** Student: {@code [int object][byte op][int n][values]} ask the grader's object. */
    public static final byte CALLBACK = 6;
    /** Grader: {@code [value result][records of the record arguments]}. */
    public static final byte CB_RETURN = 7;
    /** Grader: {@code [String message]}. */
    public static final byte CB_THROW = 8;
    // 9 and 10 were BATCH / BATCH_RETURN (many calls of one method), retired for MULTI.
    /** Either side: the empty reply to DEFINE and METHOD. */
    public static final byte ACK = 11;
    /**
     * Grader: {@code [int calls]([bool defer][int method][value target][int n][values][int k]
     * [int total]([bytes question][bytes answer])^total)...} many calls of any methods at once,
     * each with answers to callbacks: the first {@code k} are the grader's predictions of what the
     * call will ask, the others the grader's answers to questions it asked in an earlier frame. A
     * question is a CALLBACK payload as the student process writes it, its answer a CB_RETURN
     * payload. A question asked that is not among them is a callback, or with {@code defer} (for
     * questions to surfaces and materials) sent back in the reply.
     */
    public static final byte MULTI = 12;
    /**
     * Student: {@code [int calls](([byte 0][value result][records] | [byte 1][String class]
     * [String message][int n][String frames])[int u][int used prediction]^u | [byte 2][int q]
     * [bytes question]^q)... [String output]}: 2 is a call that asked questions not answered yet,
     * to be sent again with their answers.
     */
    public static final byte MULTI_RETURN = 13;

    // Value tags.
    public static final byte NULL = 0;
    public static final byte FALSE = 1;
    public static final byte TRUE = 2;
    public static final byte INT = 3;
    public static final byte LONG = 4;
    public static final byte DOUBLE = 5;
    public static final byte STRING = 6;
    public static final byte VEC3 = 7;
    public static final byte COLOR = 8;
    public static final byte RAY = 9;
    public static final byte LIGHT = 10;
    public static final byte RECORD = 11;
    /** A student object the grader defined: {@code [int handle]}. */
    public static final byte HANDLE = 12;
    public static final byte LIST = 13;
    /** A grader surface: {@code [int id][Vec3 min][Vec3 max][String name][bool convex][int count]}. */
    public static final byte REMOTE_SURFACE = 14;
    /** A grader material: {@code [int id][String name][bool lit][bool specular]}. */
    public static final byte REMOTE_MATERIAL = 15;
    /** A shading point: {@code [int answers][Vec3 x][Vec3 n][Vec3 v][value material]}. */
    public static final byte SHADING_POINT = 16;
    /**
     * A grader's light: {@code [int id][LIGHT value]} to the student process, {@code [int id]}
     * back (the grader gets its own object again).
     */
    public static final byte LIGHT_REF = 17;

    /**
     * In a MULTI frame's calls (and a record in its reply): the same as the previous call's
     * argument at the same place (a ray, or a record with the same fields, bit for bit); in a
     * reply, a record the call left as it was sent.
     */
    public static final byte AS_BEFORE = 18;
    /**
     * In a MULTI frame's calls: a record with the fields of the previous call's record at the
     * same place but its test count, {@code [long tests]} (a group counts each surface it tries).
     */
    public static final byte AS_BEFORE_TESTS = 19;

    // Callback operations.
    public static final byte OP_INTERSECT = 1;
    public static final byte OP_INTERSECTS_ANY = 2;
    public static final byte OP_KA = 3;
    public static final byte OP_DIFFUSE = 4;
    public static final byte OP_SPECULAR = 5;
    public static final byte OP_UNLIT = 6;
    public static final byte OP_AMBIENT = 7;
    public static final byte OP_TO_LIGHT = 8;
    public static final byte OP_VISIBLE = 9;
    public static final byte OP_AT_DIFFUSE = 10;
    public static final byte OP_AT_SPECULAR = 11;

    private Wire() {
    }

    /**
     * Whether a question may come back with its call instead of being asked at once (MULTI): a
     * question to the grader's surfaces or materials, which their answers alone decide, with no
     * effect on the grader's side. A shading point's questions are asked as they come.
     */
    public static boolean deferrable(byte op) {
        return op == OP_INTERSECT || op == OP_INTERSECTS_ANY || op == OP_KA || op == OP_DIFFUSE || op == OP_SPECULAR
                || op == OP_UNLIT;
    }

    /** How one side writes and reads the objects that are not plain values (handles, proxies). */
    public interface Refs {
        /** Writes a tag and data for {@code o} and returns true, or returns false if {@code o} is unknown. */
        boolean encode(Out out, Object o);

        /** Reads the data after {@code tag} (one of HANDLE, REMOTE_*, SHADING_POINT). */
        Object decode(byte tag, In in) throws IOException;
    }

    /** A growable output buffer. */
    public static final class Out {
        byte[] buf = new byte[256];
        int n;

        public void reset() {
            n = 0;
        }

        public int size() {
            return n;
        }

        private void need(int k) {
            if (n + k > buf.length) {
                buf = Arrays.copyOf(buf, Math.max(buf.length * 2, n + k));
            }
        }

        /** Appends another buffer's bytes. */
        public void write(Out other) {
            need(other.n);
            System.arraycopy(other.buf, 0, buf, n, other.n);
            n += other.n;
        }

        public void writeByte(int b) {
            need(1);
            buf[n++] = (byte) b;
        }

        public void writeInt(int v) {
            need(4);
            byte[] b = buf;
            int i = n;
            b[i] = (byte) (v >>> 24);
            b[i + 1] = (byte) (v >>> 16);
            b[i + 2] = (byte) (v >>> 8);
            b[i + 3] = (byte) v;
            n = i + 4;
        }

        /** Big-endian, as two {@link #writeInt}s; one bounds check (a render writes millions of doubles). */
        public void writeLong(long v) {
            need(8);
            byte[] b = buf;
            int i = n;
            int hi = (int) (v >>> 32);
            int lo = (int) v;
            b[i] = (byte) (hi >>> 24);
            b[i + 1] = (byte) (hi >>> 16);
            b[i + 2] = (byte) (hi >>> 8);
            b[i + 3] = (byte) hi;
            b[i + 4] = (byte) (lo >>> 24);
            b[i + 5] = (byte) (lo >>> 16);
            b[i + 6] = (byte) (lo >>> 8);
            b[i + 7] = (byte) lo;
            n = i + 8;
        }

        public void writeDouble(double d) {
            writeLong(Double.doubleToRawLongBits(d));
        }

        public void writeBoolean(boolean b) {
            writeByte(b ? 1 : 0);
        }

        public void writeString(String s) {
            if (s == null) {
                writeInt(-1);
                return;
            }
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            writeInt(b.length);
            need(b.length);
            System.arraycopy(b, 0, buf, n, b.length);
            n += b.length;
        }

        /** A length and the bytes of {@code other}. */
        public void writeBytes(Out other) {
            writeInt(other.n);
            write(other);
        }

        /** A length and {@code b}. */
        public void writeBytes(byte[] b) {
            writeInt(b.length);
            need(b.length);
            System.arraycopy(b, 0, buf, n, b.length);
            n += b.length;
        }

        /** This buffer's bytes, as a key for hash maps. */
        public Key key() {
            return new Key(Arrays.copyOf(buf, n));
        }

        public void writeVec3(Vec3 v) {
            writeDouble(v.x);
            writeDouble(v.y);
            writeDouble(v.z);
        }
    }

    /** A frame's payload being read. */
    public static final class In {
        final byte[] buf;
        int pos;
        final int end;
        /** The values being read, one inside the other ({@link #readValue}). */
        int depth;
        /** The values read so far. */
        int values;

        public In(byte[] buf, int pos, int end) {
            this.buf = buf;
            this.pos = pos;
            this.end = end;
        }

        private void need(int k) throws IOException {
            if (k < 0 || k > end - pos) {
                throw new ProtocolException("frame too short (" + k + " bytes wanted, " + (end - pos) + " left)");
            }
        }

        public boolean atEnd() {
            return pos == end;
        }

        /** Bytes not read yet. */
        public int remaining() {
            return end - pos;
        }

        public byte readByte() throws IOException {
            need(1);
            return buf[pos++];
        }

        /** The next byte, not read. */
        public byte peekByte() throws IOException {
            need(1);
            return buf[pos];
        }

        public int readInt() throws IOException {
            need(4);
            int v = ((buf[pos] & 0xff) << 24) | ((buf[pos + 1] & 0xff) << 16) | ((buf[pos + 2] & 0xff) << 8)
                    | (buf[pos + 3] & 0xff);
            pos += 4;
            return v;
        }

        public long readLong() throws IOException {
            long hi = readInt();
            long lo = readInt() & 0xffffffffL;
            return (hi << 32) | lo;
        }

        public double readDouble() throws IOException {
            return Double.longBitsToDouble(readLong());
        }

        public boolean readBoolean() throws IOException {
            return readByte() != 0;
        }

        public String readString() throws IOException {
            int len = readInt();
            if (len == -1) {
                return null;
            }
            need(len);
            String s = new String(buf, pos, len, StandardCharsets.UTF_8);
            pos += len;
            return s;
        }

        public Vec3 readVec3() throws IOException {
            return new Vec3(readDouble(), readDouble(), readDouble());
        }

        /** Bytes written by {@link Out#writeBytes}. */
        public byte[] readBytes() throws IOException {
            int len = readInt();
            need(len);
            byte[] b = Arrays.copyOfRange(buf, pos, pos + len);
            pos += len;
            return b;
        }
    }

    /** Bytes compared by content: a question or a call as a hash key. */
    public static final class Key {
        private final byte[] bytes;
        private final int hash;

        public Key(byte[] bytes) {
            this.bytes = bytes;
            this.hash = hash(bytes);
        }

        /** A hash of the bytes read eight at a time (a key is a call's inputs, a hundred bytes and more). */
        private static int hash(byte[] b) {
            long h = 1;
            int i = 0;
            for (; i + 7 < b.length; i += 8) {
                h = 31 * h + (long) LONGS.get(b, i);
            }
            for (; i < b.length; i++) {
                h = 31 * h + b[i];
            }
            return (int) (h ^ (h >>> 32));
        }

        private static final java.lang.invoke.VarHandle LONGS = java.lang.invoke.MethodHandles
                .byteArrayViewVarHandle(long[].class, java.nio.ByteOrder.BIG_ENDIAN);

        public byte[] bytes() {
            return bytes;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.hash == hash && Arrays.equals(k.bytes, bytes);
        }

        @Override
        public int hashCode() {
            return hash;
        }
    }

    /** A protocol violation, a malformed frame: the other side is broken or hostile. */
    public static final class ProtocolException extends IOException {
        private static final long serialVersionUID = 1L;

        public ProtocolException(String message) {
            super(message);
        }
    }

    /** One frame read. */
    public record Frame(byte type, int conv, In in) {
    }

    /** Writes one frame (not flushed). */
    public static void writeFrame(OutputStream out, byte type, int conv, Out payload) throws IOException {
        int len = 5 + payload.n;
        byte[] head = {(byte) (len >>> 24), (byte) (len >>> 16), (byte) (len >>> 8), (byte) len, type,
            (byte) (conv >>> 24), (byte) (conv >>> 16), (byte) (conv >>> 8), (byte) conv};
        out.write(head);
        out.write(payload.buf, 0, payload.n);
    }

    /** Reads one frame; EOFException at a clean end of stream before a frame. */
    public static Frame readFrame(DataInputStream in) throws IOException {
        int len = in.readInt();
        if (len < 5 || len > MAX_FRAME) {
            throw new ProtocolException("bad frame length " + len);
        }
        try {
            byte type = in.readByte();
            int conv = in.readInt();
            int size = len - 5;
            // The declared length is a claim: the buffer grows with the bytes that actually come.
            byte[] b = new byte[Math.min(size, READ_PIECE)];
            int got = 0;
            while (got < size) {
                if (got == b.length) {
                    b = Arrays.copyOf(b, (int) Math.min(size, 2L * b.length));
                }
                int k = in.read(b, got, b.length - got);
                if (k < 0) {
                    throw new EOFException();
                }
                got += k;
            }
            return new Frame(type, conv, new In(b, 0, size));
        } catch (EOFException e) {
            throw new ProtocolException("frame cut short (" + len + " bytes declared)");
        }
    }

    /**
     * Whether {@code b} may be sent as {@link #AS_BEFORE} after {@code a}: the same ray (bit for
     * bit), or records with the same fields (t, point, normal, surface, primitive, tests; the
     * material follows the surface).
     */
    public static boolean asBefore(Object a, Object b) {
        if (a instanceof Ray x && b instanceof Ray y) {
            return x == y || (sameBits(x.p, y.p) && sameBits(x.d, y.d) && bits(x.tMin) == bits(y.tMin)
                    && bits(x.tMax) == bits(y.tMax));
        }
        return a instanceof IntersectionRecord x && b instanceof IntersectionRecord y && sameRecord(x, y);
    }

    /** Records with the same fields, bit for bit (the material follows the surface). */
    public static boolean sameRecord(IntersectionRecord x, IntersectionRecord y) {
        return bits(x.t) == bits(y.t) && sameBits(x.point, y.point) && sameBits(x.normal, y.normal) && x.surface == y.surface
                && x.primitive == y.primitive && x.tests == y.tests;
    }

    /** Records with the same fields, bit for bit, but perhaps not the same test count ({@link #AS_BEFORE_TESTS}). */
    public static boolean sameButTests(IntersectionRecord x, IntersectionRecord y) {
        return bits(x.t) == bits(y.t) && sameBits(x.point, y.point) && sameBits(x.normal, y.normal) && x.surface == y.surface
                && x.primitive == y.primitive;
    }

    /** A copy of a record's fields, its test count included. */
    public static IntersectionRecord copyRecord(IntersectionRecord r) {
        IntersectionRecord c = new IntersectionRecord();
        c.copyFrom(r);
        c.tests = r.tests;
        return c;
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    private static boolean sameBits(Vec3 a, Vec3 b) {
        return a == b || (a != null && b != null && bits(a.x) == bits(b.x) && bits(a.y) == bits(b.y)
                && bits(a.z) == bits(b.z));
    }

    /** Writes a tagged value: plain values here, other objects through {@code refs}. */
    public static void writeValue(Out out, Object o, Refs refs) {
        if (o == null) {
            out.writeByte(NULL);
        } else if (o instanceof Boolean b) {
            out.writeByte(b ? TRUE : FALSE);
        } else if (o instanceof Integer i) {
            out.writeByte(INT);
            out.writeInt(i);
        } else if (o instanceof Long l) {
            out.writeByte(LONG);
            out.writeLong(l);
        } else if (o instanceof Double d) {
            out.writeByte(DOUBLE);
            out.writeDouble(d);
        } else if (o instanceof String s) {
            out.writeByte(STRING);
            out.writeString(s);
        } else if (o instanceof Vec3 v) {
            out.writeByte(VEC3);
            out.writeVec3(v);
        } else if (o instanceof Color c) {
            out.writeByte(COLOR);
            out.writeDouble(c.r);
            out.writeDouble(c.g);
            out.writeDouble(c.b);
        } else if (o instanceof Ray r) {
            out.writeByte(RAY);
            writeVec3OrNull(out, r.p);
            writeVec3OrNull(out, r.d);
            out.writeDouble(r.tMin);
            out.writeDouble(r.tMax);
        } else if (o instanceof PointLight l && (refs == null || !refs.encode(out, o))) {
            out.writeByte(LIGHT);
            writeVec3OrNull(out, l.position);
            writeValue(out, l.intensity, refs);
            out.writeBoolean(l.castsShadows);
            out.writeString(l.name);
        } else if (o instanceof PointLight) {
            return; // written by refs above
        } else if (o instanceof IntersectionRecord r) {
            out.writeByte(RECORD);
            writeRecord(out, r, refs);
        } else if (o instanceof List<?> list) {
            out.writeByte(LIST);
            out.writeInt(list.size());
            for (Object e : list) {
                writeValue(out, e, refs);
            }
        } else if (refs == null || !refs.encode(out, o)) {
            throw new IllegalArgumentException("cannot send a " + o.getClass().getName() + " across the process boundary");
        }
    }

    private static void writeVec3OrNull(Out out, Vec3 v) {
        if (v == null) {
            out.writeByte(NULL);
        } else {
            out.writeByte(VEC3);
            out.writeVec3(v);
        }
    }

    private static Vec3 readVec3OrNull(In in) throws IOException {
        byte tag = in.readByte();
        if (tag == NULL) {
            return null;
        }
        if (tag != VEC3) {
            throw new ProtocolException("expected a Vec3, got tag " + tag);
        }
        return in.readVec3();
    }

    /** A record's fields (not its material, which follows from its surface). */
    public static void writeRecord(Out out, IntersectionRecord r, Refs refs) {
        out.writeDouble(r.t);
        writeVec3OrNull(out, r.point);
        writeVec3OrNull(out, r.normal);
        Object s = r.surface;
        if (s != null && (refs == null || !encodes(refs, s))) {
            s = null;
        }
        writeValue(out, s, refs);
        out.writeInt(r.primitive);
        out.writeLong(r.tests);
    }

    private static boolean encodes(Refs refs, Object s) {
        Out probe = new Out();
        return refs.encode(probe, s);
    }

    /** Reads a record's fields into {@code r}; the material is the surface's. */
    public static void readRecordInto(In in, IntersectionRecord r, Refs refs) throws IOException {
        r.t = in.readDouble();
        // A point or normal that comes back with the same bits stays the same object: an untouched
        // record stays untouched, as it would in one process.
        r.point = same(r.point, readVec3OrNull(in));
        r.normal = same(r.normal, readVec3OrNull(in));
        Object s = readValue(in, refs);
        if (s != null && !(s instanceof raylab.surface.Surface)) {
            throw new ProtocolException("a record's surface is not a surface");
        }
        r.surface = (raylab.surface.Surface) s;
        r.material = r.surface == null ? null : r.surface.material();
        r.primitive = in.readInt();
        r.tests = in.readLong();
    }

    private static Vec3 same(Vec3 old, Vec3 got) {
        if (old != null && got != null && Double.doubleToRawLongBits(old.x) == Double.doubleToRawLongBits(got.x)
                && Double.doubleToRawLongBits(old.y) == Double.doubleToRawLongBits(got.y)
                && Double.doubleToRawLongBits(old.z) == Double.doubleToRawLongBits(got.z)) {
            return old;
        }
        return got;
    }

    /**
     * Reads a tagged value: at most {@link #MAX_DEPTH} deep (values inside it, through
     * {@code refs} too) and at most {@link #MAX_VALUES} in one frame.
     */
    public static Object readValue(In in, Refs refs) throws IOException {
        if (++in.values > MAX_VALUES) {
            throw new ProtocolException("more than " + MAX_VALUES + " values in one frame");
        }
        if (in.depth >= MAX_DEPTH) {
            throw new ProtocolException("values nested more than " + MAX_DEPTH + " deep");
        }
        in.depth++;
        try {
            return readTagged(in, refs);
        } finally {
            in.depth--;
        }
    }

    private static Object readTagged(In in, Refs refs) throws IOException {
        byte tag = in.readByte();
        switch (tag) {
            case NULL:
                return null;
            case FALSE:
                return Boolean.FALSE;
            case TRUE:
                return Boolean.TRUE;
            case INT:
                return in.readInt();
            case LONG:
                return in.readLong();
            case DOUBLE:
                return in.readDouble();
            case STRING:
                return in.readString();
            case VEC3:
                return in.readVec3();
            case COLOR:
                return new Color(in.readDouble(), in.readDouble(), in.readDouble());
            case RAY: {
                Vec3 p = readVec3OrNull(in);
                Vec3 d = readVec3OrNull(in);
                return new Ray(p, d, in.readDouble(), in.readDouble());
            }
            case LIGHT: {
                Vec3 p = readVec3OrNull(in);
                Object c = readValue(in, refs);
                if (c != null && !(c instanceof Color)) {
                    throw new ProtocolException("a light's intensity is not a colour");
                }
                return new PointLight(p, (Color) c, in.readBoolean(), in.readString());
            }
            case RECORD: {
                IntersectionRecord r = new IntersectionRecord();
                readRecordInto(in, r, refs);
                return r;
            }
            case LIST: {
                int n = in.readInt();
                // Each element takes at least its tag's byte; the list grows as elements are read,
                // so lists inside lists that all declare the frame's length allocate nothing ahead.
                if (n < 0 || n > in.remaining()) {
                    throw new ProtocolException("bad list length " + n + " (" + in.remaining() + " bytes left)");
                }
                List<Object> l = new ArrayList<>(Math.min(n, 16));
                for (int i = 0; i < n; i++) {
                    l.add(readValue(in, refs));
                }
                return l;
            }
            default:
                if (refs == null) {
                    throw new ProtocolException("unknown value tag " + tag);
                }
                return refs.decode(tag, in);
        }
    }
}
