package raylab.inspect;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.Deflater;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;

import raylab.math.Color;
import raylab.math.Vec3;
import raylab.scene.Scene;

/**
 * The reference ray trees of every pixel of a published scene, as data: {@code scenes/traces/NAME.trace},
 * written at release time by the reference solution ({@link #write}) and read by {@code raylab
 * inspect} and {@code check} ({@link #read}). No code of the reference is in it, only numbers about
 * the image the students already have.
 *
 * <p>Format (gzip): the line {@code RAYLAB-TRACE 1}, then (Java DataOutput) width, height, the
 * background, the surface names and kinds, the light names, then one column per quantity. Each
 * value is 24 bits: a number is its float32 rounded to at most 15 bits of mantissa (see
 * {@link #COLOUR_BITS}); an index or a count is itself; {@link #NULL} means "never computed". A column
 * is stored delta-coded and split into its three byte planes, so that the smooth fields of an
 * image (t, normals, terms) and the runs of equal indices compress well. The first column, the
 * closest surface of every pixel (0: none), says which pixels have the other columns.
 */
public final class TraceFile {
    static final String MAGIC = "RAYLAB-TRACE 1\n";
    /** The 24-bit code of a missing value (a NaN pattern no rounded float produces). */
    static final int NULL = 0xFFFFFF;
    /** Columns per hit pixel before the lights, and per light. */
    static final int HIT_COLUMNS = 12;
    static final int LIGHT_COLUMNS = 9;
    /**
     * Mantissa bits kept: t and blocker t 15 (relative error 1.5e-5), normals 13 (6e-5), colours
     * and terms 11 (2.4e-4): each well inside the comparison's 1e-3 ({@link FirstDifference#REL}).
     */
    static final int NORMAL_BITS = 13;
    static final int COLOUR_BITS = 11;

    public final int width;
    public final int height;
    public final Color background;
    final List<String> surfaces;
    final List<String> kinds;
    final List<String> lights;
    /** Column 0: surface index + 1 of every pixel; then the hit columns, over the hit pixels only. */
    final int[][] columns;
    /** Index among the hit pixels of pixel i (valid where columns[0][i] != 0). */
    private final int[] hitIndex;
    private final Scene scene;

    private TraceFile(Scene scene, int width, int height, Color background, List<String> surfaces,
            List<String> kinds, List<String> lights, int[][] columns) {
        this.scene = scene;
        this.width = width;
        this.height = height;
        this.background = background;
        this.surfaces = surfaces;
        this.kinds = kinds;
        this.lights = lights;
        this.columns = columns;
        this.hitIndex = new int[width * height];
        int n = 0;
        for (int i = 0; i < hitIndex.length; i++) {
            hitIndex[i] = columns[0][i] == 0 ? -1 : n++;
        }
    }

    /** Where the trace of {@code scenes/NAME.json} is shipped: {@code scenes/traces/NAME.trace}. */
    public static Path pathFor(Path sceneJson) {
        String name = sceneJson.getFileName().toString().replaceFirst("\\.json$", "");
        Path dir = sceneJson.toAbsolutePath().getParent();
        return dir.resolve("traces").resolve(name + ".trace");
    }

    /** Traces every pixel of the scene with the code on the class path and writes the file. */
    public static long write(Tracer tracer, Path target) throws IOException {
        Scene scene = tracer.scene();
        int w = scene.width;
        int h = scene.height;
        Map<String, Integer> names = new LinkedHashMap<>();
        List<String> kinds = new ArrayList<>();
        List<String> lightNames = scene.lights.stream().map(l -> l.name).toList();
        int nl = lightNames.size();
        int[] surf = new int[w * h];
        List<int[]> rows = new ArrayList<>();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                RayTree t = tracer.trace(x, y);
                if (!t.hit()) {
                    continue;
                }
                surf[y * w + x] = 1 + names.computeIfAbsent(t.surface, k -> {
                    kinds.add(t.kind);
                    return names.size();
                });
                int[] r = new int[HIT_COLUMNS + LIGHT_COLUMNS * nl];
                r[0] = num(t.t);
                r[1] = num(t.normal.x, NORMAL_BITS);
                r[2] = num(t.normal.y, NORMAL_BITS);
                r[3] = num(t.normal.z, NORMAL_BITS);
                r[4] = t.lit ? 1 : 0;
                r[5] = t.ambientAdded;
                colour(r, 6, t.ambient);
                colour(r, 9, t.colour);
                for (int i = 0; i < nl; i++) {
                    RayTree.Light l = t.light(lightNames.get(i));
                    int o = HIT_COLUMNS + LIGHT_COLUMNS * i;
                    r[o] = l.state.ordinal();
                    r[o + 1] = l.blocker == null ? 0 : 1 + names.computeIfAbsent(l.blocker, k -> {
                        kinds.add("?");
                        return names.size();
                    });
                    r[o + 2] = l.blocker == null ? NULL : num(l.blockerT);
                    colour(r, o + 3, l.diffuse);
                    colour(r, o + 6, l.specular);
                }
                rows.add(r);
            }
        }
        int cols = HIT_COLUMNS + LIGHT_COLUMNS * nl;
        Path tmp = target.resolveSibling(target.getFileName() + ".tmp");
        Files.createDirectories(target.toAbsolutePath().getParent());
        try (OutputStream fo = Files.newOutputStream(tmp);
                GZIPOutputStream gz = new GZIPOutputStream(new BufferedOutputStream(fo), 1 << 16) {
                    {
                        def.setLevel(Deflater.BEST_COMPRESSION);
                    }
                };
                DataOutputStream out = new DataOutputStream(gz)) {
            out.write(MAGIC.getBytes(StandardCharsets.US_ASCII));
            out.writeInt(w);
            out.writeInt(h);
            out.writeDouble(scene.background.r);
            out.writeDouble(scene.background.g);
            out.writeDouble(scene.background.b);
            out.writeInt(names.size());
            int k = 0;
            for (String n : names.keySet()) {
                out.writeUTF(n);
                out.writeUTF(kinds.get(k++));
            }
            out.writeInt(nl);
            for (String n : lightNames) {
                out.writeUTF(n);
            }
            column(out, surf);
            for (int c = 0; c < cols; c++) {
                int[] col = new int[rows.size()];
                for (int i = 0; i < col.length; i++) {
                    col[i] = rows.get(i)[c];
                }
                column(out, col);
            }
        }
        Files.move(tmp, target, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        return Files.size(target);
    }

    /** Reads a trace written for {@code scene}; an IOException when it is not one or not of this scene's size. */
    public static TraceFile read(Path file, Scene scene) throws IOException {
        try (InputStream in = new GZIPInputStream(new BufferedInputStream(Files.newInputStream(file)), 1 << 16);
                DataInputStream d = new DataInputStream(in)) {
            byte[] magic = d.readNBytes(MAGIC.length());
            if (!MAGIC.equals(new String(magic, StandardCharsets.US_ASCII))) {
                throw new IOException(file + ": not a raylab trace file");
            }
            int w = d.readInt();
            int h = d.readInt();
            if (w != scene.width || h != scene.height) {
                throw new IOException(file + " is for a " + w + "x" + h + " image, the scene is " + scene.width
                        + "x" + scene.height + ": the trace is out of date");
            }
            Color bg = new Color(d.readDouble(), d.readDouble(), d.readDouble());
            int ns = d.readInt();
            List<String> names = new ArrayList<>();
            List<String> kinds = new ArrayList<>();
            for (int i = 0; i < ns; i++) {
                names.add(d.readUTF());
                kinds.add(d.readUTF());
            }
            int nl = d.readInt();
            List<String> lights = new ArrayList<>();
            for (int i = 0; i < nl; i++) {
                lights.add(d.readUTF());
            }
            int[][] columns = new int[1 + HIT_COLUMNS + LIGHT_COLUMNS * nl][];
            columns[0] = column(d, w * h);
            int hits = 0;
            for (int v : columns[0]) {
                if (v < 0 || v > ns) {
                    throw new IOException(file + ": corrupt (surface index " + v + ")");
                }
                hits += v == 0 ? 0 : 1;
            }
            for (int c = 1; c < columns.length; c++) {
                columns[c] = column(d, hits);
            }
            return new TraceFile(scene, w, h, bg, names, kinds, lights, columns);
        } catch (java.io.EOFException | java.util.zip.ZipException e) {
            throw new IOException(file + ": truncated or corrupt trace file");
        }
    }

    /** The reference's ray tree of pixel (x, y). */
    public RayTree tree(int x, int y) {
        var ray = scene.camera.rayThroughPixelCenter(x, y);
        RayTree t = new RayTree(x, y, ray.p, ray.d);
        for (String l : lights) {
            t.light(l);
        }
        int s = columns[0][y * width + x];
        if (s == 0) {
            t.colour = background;
            return t;
        }
        int i = hitIndex[y * width + x];
        t.surface = surfaces.get(s - 1);
        t.kind = kinds.get(s - 1);
        t.t = val(col(0, i));
        t.point = ray.evaluate(t.t);
        t.normal = new Vec3(val(col(1, i)), val(col(2, i)), val(col(3, i)));
        t.lit = col(4, i) == 1;
        t.ambientAdded = col(5, i);
        t.ambient = colour(i, 6);
        t.colour = colour(i, 9);
        for (int j = 0; j < lights.size(); j++) {
            RayTree.Light l = t.light(lights.get(j));
            int o = HIT_COLUMNS + LIGHT_COLUMNS * j;
            l.state = RayTree.State.values()[col(o, i)];
            int b = col(o + 1, i);
            l.blocker = b == 0 ? null : surfaces.get(b - 1);
            l.blockerT = b == 0 ? Double.NaN : val(col(o + 2, i));
            l.diffuse = colour(i, o + 3);
            l.specular = colour(i, o + 6);
        }
        return t;
    }

    /** The linear colour of pixel (x, y) as the reference traced it (one ray through the centre). */
    public Color colourAt(int x, int y) {
        int s = columns[0][y * width + x];
        return s == 0 ? background : colour(hitIndex[y * width + x], 9);
    }

    private int col(int c, int i) {
        return columns[1 + c][i];
    }

    private Color colour(int i, int c) {
        int r = col(c, i);
        return r == NULL ? null : new Color(val(r), val(col(c + 1, i)), val(col(c + 2, i)));
    }

    /** The 24-bit code of a number: its float32 rounded to 15 mantissa bits. */
    static int num(double v) {
        return num(v, 15);
    }

    /**
     * The 24-bit code of a number kept to {@code mantissa} bits (at most 15): the float32's sign,
     * exponent and top mantissa bits, rounded to nearest; the bits below are zero, so that they
     * cost nothing after compression.
     */
    static int num(double v, int mantissa) {
        int bits = Float.floatToIntBits((float) v);
        if (Float.isNaN((float) v)) {
            return 0x7FC000;
        }
        int drop = 23 - mantissa;
        int r = ((bits + (1 << (drop - 1))) >>> drop) << (drop - 8);
        if ((bits & 0x7F800000) != 0x7F800000 && (r & 0x7F8000) == 0x7F8000) {
            r = (bits >>> drop) << (drop - 8); // rounding up would overflow to infinity: truncate instead
        }
        return r & 0xFFFFFF;
    }

    /** The number of a 24-bit code. */
    static double val(int code) {
        return Float.intBitsToFloat(code << 8);
    }

    private static void colour(int[] r, int at, Color c) {
        r[at] = c == null ? NULL : num(c.r, COLOUR_BITS);
        r[at + 1] = c == null ? NULL : num(c.g, COLOUR_BITS);
        r[at + 2] = c == null ? NULL : num(c.b, COLOUR_BITS);
    }

    /** A column: deltas of the 24-bit values, as three byte planes (high, middle, low). */
    private static void column(DataOutputStream out, int[] v) throws IOException {
        int[] delta = new int[v.length];
        int prev = 0;
        for (int i = 0; i < v.length; i++) {
            delta[i] = (v[i] - prev) & 0xFFFFFF;
            prev = v[i];
        }
        byte[] plane = new byte[v.length];
        for (int shift = 16; shift >= 0; shift -= 8) {
            for (int i = 0; i < v.length; i++) {
                plane[i] = (byte) (delta[i] >>> shift);
            }
            out.write(plane);
        }
    }

    private static int[] column(DataInputStream in, int n) throws IOException {
        int[] v = new int[n];
        for (int shift = 16; shift >= 0; shift -= 8) {
            byte[] plane = new byte[n];
            in.readFully(plane);
            for (int i = 0; i < n; i++) {
                v[i] |= (plane[i] & 0xFF) << shift;
            }
        }
        int prev = 0;
        for (int i = 0; i < n; i++) {
            v[i] = (v[i] + prev) & 0xFFFFFF;
            prev = v[i];
        }
        return v;
    }
}
