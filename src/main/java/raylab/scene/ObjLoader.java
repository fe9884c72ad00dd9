package raylab.scene;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import raylab.math.Vec3;

/**
 * Reads the triangles of a Wavefront OBJ file.
 *
 * <p>Understood: {@code v x y z [w]} (further numbers, such as vertex colours, are ignored) and
 * {@code f} with three or more vertices in the forms {@code i}, {@code i/t}, {@code i//n},
 * {@code i/t/n}, where a negative i counts back from the last vertex defined so far (−1 is the
 * last one). A face with k vertices becomes k − 2 triangles fanned around its first vertex.
 * Everything else (vt, vn, vp, o, g, s, usemtl, mtllib, l, unknown statements, comments after
 * '#', blank lines) is ignored. Errors name the file and line: {@code bunny.obj:12: ...}.
 */
public final class ObjLoader {
    private ObjLoader() {
    }

    /** A problem in an OBJ file, as one line starting with the file name (and line number). */
    public static final class ObjException extends Exception {
        private static final long serialVersionUID = 1L;

        public ObjException(String oneLine) {
            super(oneLine);
        }
    }

    private static final Pattern NUMBER =
            Pattern.compile("[+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?");
    private static final Pattern FACE_VERTEX =
            Pattern.compile("([+-]?\\d+)(?:/([+-]?\\d*)(?:/([+-]?\\d+))?)?");

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
        byte[] bytes;
        try {
            if (Files.isDirectory(file)) {
                throw new ObjException(display + ": is a directory, not an OBJ file");
            }
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new ObjException(display + ": no such file");
        } catch (AccessDeniedException e) {
            throw new ObjException(display + ": permission denied");
        } catch (IOException e) {
            throw new ObjException(display + ": cannot read: " + JsonTree.firstLine(e.getMessage()));
        }
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new ObjException(display + ": not a text file (NUL byte at offset " + i
                        + "); an OBJ file is text");
            }
        }
        // OBJ statements are ASCII; ISO-8859-1 reads any byte, so comments in other encodings pass.
        return parse(new String(bytes, StandardCharsets.ISO_8859_1), display);
    }

    /** The triangles of OBJ text; {@code display} names it in error messages. */
    public static List<Vec3[]> parse(String text, String display) throws ObjException {
        List<Vec3> vertices = new ArrayList<>();
        List<Vec3[]> triangles = new ArrayList<>();
        String[] lines = text.split("\r\n|\r|\n", -1);
        for (int ln = 0; ln < lines.length; ln++) {
            String line = lines[ln];
            int hash = line.indexOf('#');
            if (hash >= 0) {
                line = line.substring(0, hash);
            }
            line = line.strip();
            if (line.isEmpty()) {
                continue;
            }
            String[] tok = line.split("\\s+");
            String where = display + ":" + (ln + 1) + ": ";
            if (tok[0].equals("v")) {
                if (tok.length < 4) {
                    throw new ObjException(where + "a vertex needs 3 coordinates (v x y z), got "
                            + (tok.length - 1));
                }
                double[] xyz = new double[3];
                for (int k = 1; k < tok.length; k++) {
                    double d = number(tok[k], where);
                    if (k <= 3) {
                        xyz[k - 1] = d;
                    }
                }
                vertices.add(new Vec3(xyz[0], xyz[1], xyz[2]));
            } else if (tok[0].equals("f")) {
                int n = tok.length - 1;
                if (n < 3) {
                    throw new ObjException(where + "a face needs at least 3 vertices, got " + n);
                }
                Vec3[] face = new Vec3[n];
                for (int k = 0; k < n; k++) {
                    face[k] = vertices.get(vertexIndex(tok[k + 1], vertices.size(), where));
                }
                for (int k = 1; k + 1 < n; k++) {
                    triangles.add(new Vec3[] {face[0], face[k], face[k + 1]});
                }
            }
            // Anything else (vt, vn, vp, o, g, s, usemtl, mtllib, l, unknown) is ignored.
        }
        if (triangles.isEmpty()) {
            throw new ObjException(display + ": no faces (a mesh needs at least one 'f' line)");
        }
        return triangles;
    }

    private static double number(String s, String where) throws ObjException {
        if (!NUMBER.matcher(s).matches()) {
            throw new ObjException(where + "expected a number, got '" + s + "'");
        }
        double d = Double.parseDouble(s);
        if (!Double.isFinite(d)) {
            throw new ObjException(where + "the number " + s + " is too large (it overflows to"
                    + " infinity)");
        }
        return d;
    }

    /** The 0-based vertex index of a face vertex such as "3", "3/1", "3//2", "-1/1/1". */
    private static int vertexIndex(String s, int defined, String where) throws ObjException {
        Matcher m = FACE_VERTEX.matcher(s);
        if (!m.matches()) {
            throw new ObjException(where + "malformed face vertex '" + s
                    + "' (expected i, i/t, i//n or i/t/n with integer indices)");
        }
        long i;
        try {
            i = Long.parseLong(m.group(1));
        } catch (NumberFormatException e) {
            i = m.group(1).startsWith("-") ? Long.MIN_VALUE : Long.MAX_VALUE;
        }
        String have = defined == 1 ? "only 1 vertex is" : (defined == 0 ? "no vertices are"
                : "only " + defined + " vertices are");
        if (i == 0) {
            throw new ObjException(where + "vertex index 0 is invalid (OBJ indices start at 1)");
        }
        if (i > 0) {
            if (i > defined) {
                throw new ObjException(where + "vertex index " + m.group(1) + " is out of range: "
                        + have + " defined before this line");
            }
            return (int) (i - 1);
        }
        if (i < -(long) defined) {
            throw new ObjException(where + "relative vertex index " + m.group(1)
                    + " is out of range: " + have + " defined before this line");
        }
        return (int) (defined + i);
    }
}
