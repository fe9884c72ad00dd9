package raylab.scene;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import raylab.math.Vec3;

/**
 * Reads the triangles of a Wavefront OBJ file.
 *
 * <p>Understood: {@code v x y z [w]} (further numbers, such as vertex colours, are ignored) and
 * {@code f} with three or more vertices in the forms {@code i}, {@code i/t}, {@code i//n},
 * {@code i/t/n}, where a negative i counts back from the last vertex defined so far (−1 is the
 * last one). A face with k vertices becomes k − 2 triangles fanned around its first vertex.
 * Everything else (vt, vn, vp, o, g, s, usemtl, mtllib, l, unknown statements, comments after
 * '#', blank lines) is ignored; a UTF-8 byte order mark at the start is skipped. Errors name the
 * file and line: {@code bunny.obj:12: ...}.
 *
 * <p>The reader is a hand-written scanner over the file's bytes (no regular expressions, no
 * strings per line): vertices go to one {@code double[]}, faces to one {@code int[]} of vertex
 * indices. Only regular files are read (not FIFOs or devices, which could block or never end),
 * and at most {@link #maxBytes()} bytes.
 *
 * <p>One parser for one format (Wavefront OBJ's triangles).
 */
public final class ObjLoader {
    private ObjLoader() {
    }

    /** Default largest OBJ file read, in bytes (512 MiB); system property raylab.obj.maxBytes. */
    public static final long DEFAULT_MAX_BYTES = 512L << 20;

    /** A problem in an OBJ file, as one line starting with the file name (and line number). */
    public static final class ObjException extends Exception {
        private static final long serialVersionUID = 1L;

        public ObjException(String oneLine) {
            super(oneLine);
        }
    }

    /**
     * An indexed triangle mesh: vertex j at {@code vertices[3 j .. 3 j + 3)}, triangle i made of
     * the vertices {@code indices[3 i .. 3 i + 3)}, in file order.
     */
    public record Indexed(double[] vertices, int[] indices) {
        /** Number of triangles. */
        public int triangleCount() {
            return indices.length / 3;
        }

        /** The triangles as a, b, c (nine numbers each), in file order. */
        public double[] triangleVertices() {
            double[] out = new double[3 * indices.length];
            for (int i = 0; i < indices.length; i++) {
                System.arraycopy(vertices, 3 * indices[i], out, 3 * i, 3);
            }
            return out;
        }
    }

    /** The largest OBJ file read, in bytes. */
    public static long maxBytes() {
        String s = System.getProperty("raylab.obj.maxBytes");
        if (s != null) {
            try {
                return Long.parseLong(s.strip());
            } catch (NumberFormatException e) {
                return DEFAULT_MAX_BYTES;
            }
        }
        return DEFAULT_MAX_BYTES;
    }

    /** The triangles of an OBJ file, in file order, each as its three vertices. */
    public static List<Vec3[]> readTriangles(Path file) throws ObjException {
        return readTriangles(file, file.toString());
    }

    /**
     * The triangles of an OBJ file, in file order, each as its three vertices.
     *
     * @param display how to name the file in error messages
     */
    public static List<Vec3[]> readTriangles(Path file, String display) throws ObjException {
        return toVec3(read(file, display));
    }

    /** The mesh of an OBJ file; {@code display} names it in error messages. */
    public static Indexed read(Path file, String display) throws ObjException {
        byte[] bytes = readBytes(file, display, maxBytes());
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new ObjException(display + ": not a text file (NUL byte at offset " + i
                        + "); an OBJ file is text");
            }
        }
        return parse(bytes, display);
    }

    /** The file's bytes: only for a regular file of at most {@code max} bytes. */
    static byte[] readBytes(Path file, String display, long max) throws ObjException {
        try {
            if (Files.isDirectory(file)) {
                throw new ObjException(display + ": is a directory, not an OBJ file");
            }
            BasicFileAttributes attrs = Files.readAttributes(file, BasicFileAttributes.class);
            if (!attrs.isRegularFile()) {
                throw new ObjException(display + ": not a regular file (a device, FIFO or socket);"
                        + " an OBJ file must be a regular file");
            }
            if (attrs.size() > max) {
                throw new ObjException(display + ": too large (" + attrs.size() + " bytes; the limit"
                        + " is " + max + " bytes, set by -Draylab.obj.maxBytes)");
            }
            try (InputStream in = Files.newInputStream(file)) {
                // Read at most max + 1 bytes: a file that grew since its size was taken is caught.
                byte[] bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, max + 1));
                if (bytes.length > max) {
                    throw new ObjException(display + ": too large (more than " + max + " bytes; the"
                            + " limit is " + max + " bytes, set by -Draylab.obj.maxBytes)");
                }
                return bytes;
            }
        } catch (NoSuchFileException e) {
            throw new ObjException(display + ": no such file");
        } catch (AccessDeniedException e) {
            throw new ObjException(display + ": permission denied");
        } catch (IOException e) {
            throw new ObjException(display + ": cannot read: " + JsonTree.firstLine(e.getMessage()));
        } catch (OutOfMemoryError e) {
            throw new ObjException(display + ": too large to read into memory");
        }
    }

    /** The triangles of OBJ text; {@code display} names it in error messages. */
    public static List<Vec3[]> parse(String text, String display) throws ObjException {
        // OBJ statements are ASCII; ISO-8859-1 maps each char to one byte, as the file reader does.
        return toVec3(parse(text.getBytes(StandardCharsets.ISO_8859_1), display));
    }

    private static List<Vec3[]> toVec3(Indexed mesh) {
        double[] v = mesh.vertices();
        Vec3[] vs = new Vec3[v.length / 3];
        for (int j = 0; j < vs.length; j++) {
            vs[j] = new Vec3(v[3 * j], v[3 * j + 1], v[3 * j + 2]);
        }
        int[] idx = mesh.indices();
        List<Vec3[]> out = new ArrayList<>(idx.length / 3);
        for (int i = 0; i < idx.length; i += 3) {
            out.add(new Vec3[] {vs[idx[i]], vs[idx[i + 1]], vs[idx[i + 2]]});
        }
        return out;
    }

    /** The mesh of OBJ bytes; {@code display} names it in error messages. */
    public static Indexed parse(byte[] b, String display) throws ObjException {
        return new Scanner(b, display).run();
    }

    /** One pass over the bytes, line by line, token by token. */
    private static final class Scanner {
        private final byte[] b;
        private final String display;
        private double[] verts = new double[3 * 1024];
        private int nv;
        private int[] idx = new int[3 * 1024];
        private int ni;
        private int line;
        // Tokens of the current line: start and end offsets.
        private int[] tokStart = new int[16];
        private int[] tokEnd = new int[16];
        private int[] face = new int[16];

        Scanner(byte[] b, String display) {
            this.b = b;
            this.display = display;
        }

        Indexed run() throws ObjException {
            int pos = 0;
            int len = b.length;
            if (len >= 3 && b[0] == (byte) 0xEF && b[1] == (byte) 0xBB && b[2] == (byte) 0xBF) {
                pos = 3; // UTF-8 byte order mark
            }
            line = 0;
            while (pos <= len) {
                line++;
                int end = pos;
                while (end < len && b[end] != '\n' && b[end] != '\r') {
                    end++;
                }
                statement(pos, end);
                if (end >= len) {
                    break;
                }
                pos = end + (b[end] == '\r' && end + 1 < len && b[end + 1] == '\n' ? 2 : 1);
                if (pos == len) {
                    break; // a final line break ends the last line; no empty line follows
                }
            }
            if (ni == 0) {
                throw new ObjException(display + ": no faces (a mesh needs at least one 'f' line)");
            }
            return new Indexed(Arrays.copyOf(verts, 3 * nv), Arrays.copyOf(idx, ni));
        }

        private static boolean space(byte c) {
            return c == ' ' || c == '\t' || c == 0x0B || c == '\f' || (c >= 0x1C && c <= 0x1F);
        }

        private void statement(int from, int to) throws ObjException {
            // Skip leading blanks; the keyword decides whether the line matters at all.
            int p = from;
            while (p < to && space(b[p])) {
                p++;
            }
            if (p >= to || b[p] != 'v' && b[p] != 'f') {
                return;
            }
            boolean vertex = b[p] == 'v';
            if (p + 1 < to && !space(b[p + 1]) && b[p + 1] != '#') {
                return; // vt, vn, vp, fo, ...: other statements
            }
            int n = tokens(p + 1, to);
            if (vertex) {
                vertex(n);
            } else {
                face(n);
            }
        }

        /** Splits [from, to) at blanks up to a '#'; returns the number of tokens. */
        private int tokens(int from, int to) {
            int n = 0;
            int p = from;
            while (true) {
                while (p < to && space(b[p])) {
                    p++;
                }
                if (p >= to || b[p] == '#') {
                    return n;
                }
                int s = p;
                while (p < to && !space(b[p]) && b[p] != '#') {
                    p++;
                }
                if (n == tokStart.length) {
                    tokStart = Arrays.copyOf(tokStart, 2 * n);
                    tokEnd = Arrays.copyOf(tokEnd, 2 * n);
                }
                tokStart[n] = s;
                tokEnd[n] = p;
                n++;
            }
        }

        private String where() {
            return display + ":" + line + ": ";
        }

        private String text(int k) {
            return new String(b, tokStart[k], tokEnd[k] - tokStart[k], StandardCharsets.ISO_8859_1);
        }

        private void vertex(int n) throws ObjException {
            if (n < 3) {
                throw new ObjException(where() + "a vertex needs 3 coordinates (v x y z), got " + n);
            }
            if (3 * nv + 3 > verts.length) {
                verts = Arrays.copyOf(verts, 2 * verts.length);
            }
            for (int k = 0; k < n; k++) {
                double d = number(k);
                if (k < 3) {
                    verts[3 * nv + k] = d;
                }
            }
            nv++;
        }

        private static final double[] POW10 = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9,
            1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

        /**
         * Token k as a number of the form [+-](digits[.digits] | .digits)[(e|E)[+-]digits]. When
         * it has at most 15 significant digits and a decimal exponent of at most 22 in magnitude,
         * one exactly representable integer times or divided by one exact power of ten gives the
         * correctly rounded double (Clinger's fast path); otherwise Double.parseDouble.
         */
        private double number(int k) throws ObjException {
            int p = tokStart[k];
            int end = tokEnd[k];
            boolean negative = false;
            if (p < end && (b[p] == '+' || b[p] == '-')) {
                negative = b[p] == '-';
                p++;
            }
            long mantissa = 0;
            int digits = 0; // significant digits in mantissa
            int intDigits = 0;
            int fracDigits = 0;
            int scale = 0; // decimal exponent from digits dropped or after the point
            boolean exact = true;
            while (p < end && b[p] >= '0' && b[p] <= '9') {
                int d = b[p] - '0';
                if (digits > 0 || d != 0) {
                    if (digits < 18) {
                        mantissa = 10 * mantissa + d;
                        digits++;
                    } else {
                        exact = false;
                    }
                }
                intDigits++;
                p++;
            }
            if (p < end && b[p] == '.') {
                p++;
                while (p < end && b[p] >= '0' && b[p] <= '9') {
                    int d = b[p] - '0';
                    if (digits > 0 || d != 0) {
                        if (digits < 18) {
                            mantissa = 10 * mantissa + d;
                            digits++;
                            scale--;
                        } else {
                            exact = false;
                        }
                    } else {
                        scale--; // a leading zero after the point
                    }
                    fracDigits++;
                    p++;
                }
            }
            if (intDigits + fracDigits == 0) {
                throw notANumber(k);
            }
            int exp = 0;
            if (p < end && (b[p] == 'e' || b[p] == 'E')) {
                p++;
                boolean expNegative = false;
                if (p < end && (b[p] == '+' || b[p] == '-')) {
                    expNegative = b[p] == '-';
                    p++;
                }
                int expDigits = 0;
                while (p < end && b[p] >= '0' && b[p] <= '9') {
                    if (exp < 100000) {
                        exp = 10 * exp + (b[p] - '0');
                    }
                    expDigits++;
                    p++;
                }
                if (expDigits == 0) {
                    throw notANumber(k);
                }
                if (expNegative) {
                    exp = -exp;
                }
            }
            if (p != end) {
                throw notANumber(k);
            }
            double value;
            int e10 = scale + exp;
            if (exact && digits <= 15 && e10 >= -22 && e10 <= 22) {
                value = e10 >= 0 ? mantissa * POW10[e10] : mantissa / POW10[-e10];
                if (negative) {
                    value = -value;
                }
            } else {
                value = Double.parseDouble(text(k));
            }
            if (!Double.isFinite(value)) {
                throw new ObjException(where() + "the number " + text(k) + " is too large (it overflows to"
                        + " infinity)");
            }
            return value;
        }

        private ObjException notANumber(int k) {
            return new ObjException(where() + "expected a number, got '" + text(k) + "'");
        }

        private void face(int n) throws ObjException {
            if (n < 3) {
                throw new ObjException(where() + "a face needs at least 3 vertices, got " + n);
            }
            if (face.length < n) {
                face = new int[n];
            }
            for (int k = 0; k < n; k++) {
                face[k] = vertexIndex(k);
            }
            int need = ni + 3 * (n - 2);
            if (need > idx.length) {
                idx = Arrays.copyOf(idx, Math.max(need, 2 * idx.length));
            }
            for (int k = 1; k + 1 < n; k++) {
                idx[ni++] = face[0];
                idx[ni++] = face[k];
                idx[ni++] = face[k + 1];
            }
        }

        /** Index of an optionally signed run of digits at p, or -1 if there is none. */
        private int digitsEnd(int p, int end) {
            if (p < end && (b[p] == '+' || b[p] == '-')) {
                p++;
            }
            int s = p;
            while (p < end && b[p] >= '0' && b[p] <= '9') {
                p++;
            }
            return p > s ? p : -1;
        }

        /** The 0-based vertex index of face vertex k, such as "3", "3/1", "3//2", "-1/1/1". */
        private int vertexIndex(int k) throws ObjException {
            int s = tokStart[k];
            int end = tokEnd[k];
            // i, i/t, i//n or i/t/n: i and n signed integers, t optional (possibly signed digits).
            int iEnd = digitsEnd(s, end);
            boolean ok = iEnd > 0;
            if (ok && iEnd < end) {
                ok = b[iEnd] == '/';
                int p = iEnd + 1;
                if (ok) {
                    if (p < end && (b[p] == '+' || b[p] == '-')) {
                        p++;
                    }
                    while (p < end && b[p] >= '0' && b[p] <= '9') {
                        p++;
                    }
                    if (p < end) {
                        ok = b[p] == '/' && digitsEnd(p + 1, end) == end;
                    }
                }
            }
            if (!ok) {
                throw new ObjException(where() + "malformed face vertex '" + text(k)
                        + "' (expected i, i/t, i//n or i/t/n with integer indices)");
            }
            boolean negative = b[s] == '-';
            int p = b[s] == '+' || b[s] == '-' ? s + 1 : s;
            long i = 0;
            for (; p < iEnd; p++) {
                i = 10 * i + (b[p] - '0');
                if (i > Integer.MAX_VALUE) {
                    i = Long.MAX_VALUE / 16; // far beyond any vertex count; keeps the sign test
                    break;
                }
            }
            if (negative) {
                i = -i;
            }
            int defined = nv;
            if (i == 0) {
                throw new ObjException(where() + "vertex index 0 is invalid (OBJ indices start at 1)");
            }
            String group = i > defined || i < -(long) defined
                    ? new String(b, s, iEnd - s, StandardCharsets.ISO_8859_1) : null;
            String have = defined == 1 ? "only 1 vertex is" : (defined == 0 ? "no vertices are"
                    : "only " + defined + " vertices are");
            if (i > 0) {
                if (i > defined) {
                    throw new ObjException(where() + "vertex index " + group + " is out of range: "
                            + have + " defined before this line");
                }
                return (int) (i - 1);
            }
            if (i < -(long) defined) {
                throw new ObjException(where() + "relative vertex index " + group
                        + " is out of range: " + have + " defined before this line");
            }
            return (int) (defined + i);
        }
    }
}
