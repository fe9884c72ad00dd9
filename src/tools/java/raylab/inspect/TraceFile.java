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
 * <p>Format (gzip): the line {@code RAYLAB-TRACE 2}, then (Java DataOutput) width, height, the
 * stride (every stride-th pixel of every stride-th row is traced: 1 for all of them), the
 * background, the surface names and kinds, the light names, then one column per quantity. Each
 * value is 24 bits: t is its float32 rounded to {@link #T_BITS} bits of mantissa, a normal or a
 * colour is fixed-point (see {@link #COLOUR_SCALE}), an index or a count is itself; {@link #NULL}
 * means "never computed". The first column, the closest surface of every pixel (0: none), says
 * which pixels have the other columns; it is stored delta-coded. The other columns are stored as
 * the residuals of a prediction that the reader repeats from the values it has already read
 * ({@code Predictor}): a pixel's value from its left, upper and upper-left neighbours on the same
 * surface (LOCO-I's median edge detector), the green and blue of a colour from its red and a
 * neighbour's ratio (a material's colour is a constant ratio over a surface), and the pixel's colour
 * L from the sum of its terms ka·Ia + Σ (diffuse + specular), which it equals up to rounding.
 * Residuals are zigzag-coded and split into their three byte planes, so that the many small ones
 * compress well.
 *
 * <p>One file format, its writer and its reader side by side so that each field is read as it is
 * written.
 */
public final class TraceFile {
    /** The format's version, in the first line. */
    static final int VERSION = 2;
    static final String MAGIC = "RAYLAB-TRACE " + VERSION + "\n";
    /** The 24-bit code of a missing value (a NaN pattern no rounded float produces). */
    static final int NULL = 0xFFFFFF;
    /** Columns per hit pixel before the lights, and per light. */
    static final int HIT_COLUMNS = 12;
    static final int LIGHT_COLUMNS = 9;
    /**
     * The roundings, each well inside the comparison's 3e-3 ({@link FirstDifference#REL}, absolute
     * for normals and for colours up to 1): t and blocker t keep 11 mantissa bits of their float32
     * (relative error at most 2.4e-4, so that the point p + t·d moves by less than 2.4e-4·t·|d|);
     * a normal's components are fixed-point in steps of 1/{@value #NORMAL_SCALE} (error 4.9e-4),
     * the terms ka·Ia, diffuse and specular in steps of 1/{@value #TERM_SCALE} (4.9e-4), the
     * pixel's colour in steps of 1/{@value #COLOUR_SCALE} (1.2e-4: within one 8-bit step of the
     * reference image even where the sRGB curve is steepest, near black, as the release checks).
     * The traces' size is mostly these rounding bits: each bit less is about a bit less per value
     * of a smooth field.
     */
    static final int T_BITS = 11;
    static final int NORMAL_SCALE = 1024;
    static final int TERM_SCALE = 1024;
    static final int COLOUR_SCALE = 4096;
    /** Fixed-point values are stored offset by 2^23, so that their codes order as they do. */
    private static final int OFFSET = 1 << 23;
    /** The version and roundings: a trace written with other ones is another file (the release's cache key). */
    public static final String FORMAT = VERSION + "." + T_BITS + "." + NORMAL_SCALE + "." + TERM_SCALE + "."
            + COLOUR_SCALE;

    /**
     * The most pixels a trace keeps: a larger scene's trace would keep every k-th pixel of every
     * k-th row, k the smallest that fits ({@code inspect} and {@code check} then show the nearest
     * traced pixel). 1,000,000 keeps every pixel of every published scene (the largest,
     * showcase.json, is 1280×720): the 15 traces are 1.80 MB, the starter 2.44 MB as a .tar.gz
     * (README, "See why a pixel is wrong"; the release writes them, {@code ReferenceTraces}).
     */
    public static final int MAX_TRACED = 1_000_000;

    /** The smallest k for which every k-th pixel of every k-th row is at most {@link #MAX_TRACED} pixels. */
    public static int strideFor(int width, int height) {
        int k = 1;
        while ((long) ((width + k - 1) / k) * ((height + k - 1) / k) > MAX_TRACED) {
            k++;
        }
        return k;
    }

    public final int width;
    public final int height;
    /**
     * Every stride-th pixel of every stride-th row is traced, from (0, 0): 1 for every pixel; a
     * larger scene's trace keeps fewer ({@link #traced(int, int)} gives the pixel a click stands for).
     */
    public final int stride;
    /** The traced grid's size. */
    private final int gw;
    public final Color background;
    final List<String> surfaces;
    final List<String> kinds;
    final List<String> lights;
    /** Column 0: surface index + 1 of every pixel; then the hit columns, over the hit pixels only. */
    final int[][] columns;
    /** Index among the hit pixels of pixel i (valid where columns[0][i] != 0). */
    private final int[] hitIndex;
    private final Scene scene;

    private TraceFile(Scene scene, int width, int height, int stride, Color background, List<String> surfaces,
            List<String> kinds, List<String> lights, int[][] columns) {
        this.scene = scene;
        this.width = width;
        this.height = height;
        this.stride = stride;
        this.gw = (width + stride - 1) / stride;
        this.background = background;
        this.surfaces = surfaces;
        this.kinds = kinds;
        this.lights = lights;
        this.columns = columns;
        this.hitIndex = new int[columns[0].length];
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
        return write(tracer, target, 1);
    }

    /** Traces every stride-th pixel of every stride-th row and writes the file. */
    public static long write(Tracer tracer, Path target, int stride) throws IOException {
        if (stride < 1) {
            throw new IllegalArgumentException("stride " + stride);
        }
        Scene scene = tracer.scene();
        int fullW = scene.width;
        int fullH = scene.height;
        int w = (fullW + stride - 1) / stride;
        int h = (fullH + stride - 1) / stride;
        Map<String, Integer> names = new LinkedHashMap<>();
        List<String> kinds = new ArrayList<>();
        List<String> lightNames = scene.lights.stream().map(l -> l.name).toList();
        int nl = lightNames.size();
        int[] surf = new int[w * h];
        List<int[]> rows = new ArrayList<>();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                RayTree t = tracer.trace(x * stride, y * stride);
                if (!t.hit()) {
                    continue;
                }
                surf[y * w + x] = 1 + names.computeIfAbsent(t.surface, k -> {
                    kinds.add(t.kind);
                    return names.size();
                });
                int[] r = new int[HIT_COLUMNS + LIGHT_COLUMNS * nl];
                r[0] = num(t.t);
                r[1] = fixed(t.normal.x, NORMAL_SCALE);
                r[2] = fixed(t.normal.y, NORMAL_SCALE);
                r[3] = fixed(t.normal.z, NORMAL_SCALE);
                r[4] = t.lit ? 1 : 0;
                r[5] = t.ambientAdded;
                colour(r, 6, t.ambient, TERM_SCALE);
                colour(r, 9, t.colour, COLOUR_SCALE);
                for (int i = 0; i < nl; i++) {
                    RayTree.Light l = t.light(lightNames.get(i));
                    int o = HIT_COLUMNS + LIGHT_COLUMNS * i;
                    r[o] = l.state.ordinal();
                    r[o + 1] = l.blocker == null ? 0 : 1 + names.computeIfAbsent(l.blocker, k -> {
                        kinds.add("?");
                        return names.size();
                    });
                    r[o + 2] = l.blocker == null ? NULL : num(l.blockerT);
                    colour(r, o + 3, l.diffuse, TERM_SCALE);
                    colour(r, o + 6, l.specular, TERM_SCALE);
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
            out.writeInt(fullW);
            out.writeInt(fullH);
            out.writeInt(stride);
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
            int[][] columns = new int[cols][rows.size()];
            for (int c = 0; c < cols; c++) {
                for (int i = 0; i < rows.size(); i++) {
                    columns[c][i] = rows.get(i)[c];
                }
            }
            Predictor p = new Predictor(w, h, surf, nl, columns);
            for (int c : p.order) {
                int[] residual = new int[rows.size()];
                for (int i = 0; i < residual.length; i++) {
                    int predicted = p.predict(c, i);
                    residual[i] = zigzag(p.coded(c, i) - predicted);
                }
                planes(out, residual);
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
            int fullW = d.readInt();
            int fullH = d.readInt();
            if (fullW != scene.width || fullH != scene.height) {
                throw new IOException(file + " is for a " + fullW + "x" + fullH + " image, the scene is " + scene.width
                        + "x" + scene.height + ": the trace is out of date");
            }
            int stride = d.readInt();
            if (stride < 1 || stride > Math.max(fullW, fullH)) {
                throw new IOException(file + ": corrupt (stride " + stride + ")");
            }
            int w = (fullW + stride - 1) / stride;
            int h = (fullH + stride - 1) / stride;
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
            int[][] hit = new int[columns.length - 1][hits];
            Predictor p = new Predictor(w, h, columns[0], nl, hit);
            for (int c : p.order) {
                int[] residual = planes(d, hits);
                for (int i = 0; i < hits; i++) {
                    p.decode(c, i, (p.predict(c, i) + unzigzag(residual[i])) & 0xFFFFFF);
                }
            }
            System.arraycopy(hit, 0, columns, 1, hit.length);
            return new TraceFile(scene, fullW, fullH, stride, bg, names, kinds, lights, columns);
        } catch (java.io.EOFException | java.util.zip.ZipException e) {
            throw new IOException(file + ": truncated or corrupt trace file");
        }
    }

    /** The traced pixel nearest to (x, y): itself when the trace has every pixel. */
    public int[] traced(int x, int y) {
        int sx = Math.min((int) Math.round((double) x / stride), gw - 1) * stride;
        int sy = Math.min((int) Math.round((double) y / stride), (height + stride - 1) / stride - 1) * stride;
        return new int[] {sx, sy};
    }

    /** Whether pixel (x, y) is one the trace has. */
    public boolean isTraced(int x, int y) {
        return x % stride == 0 && y % stride == 0;
    }

    private int cell(int x, int y) {
        int[] p = traced(x, y);
        return p[1] / stride * gw + p[0] / stride;
    }

    /** The reference's ray tree of the traced pixel nearest to (x, y) ({@link #traced}). */
    public RayTree tree(int px, int py) {
        int[] p = traced(px, py);
        int x = p[0];
        int y = p[1];
        var ray = scene.camera.rayThroughPixelCenter(x, y);
        RayTree t = new RayTree(x, y, ray.p, ray.d);
        for (String l : lights) {
            t.light(l);
        }
        int s = columns[0][cell(x, y)];
        if (s == 0) {
            t.colour = background;
            return t;
        }
        int i = hitIndex[cell(x, y)];
        t.surface = surfaces.get(s - 1);
        t.kind = kinds.get(s - 1);
        t.t = val(col(0, i));
        t.point = ray.evaluate(t.t);
        t.normal = new Vec3(fixedVal(col(1, i), NORMAL_SCALE), fixedVal(col(2, i), NORMAL_SCALE),
                fixedVal(col(3, i), NORMAL_SCALE));
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

    /** The linear colour of the traced pixel nearest to (x, y) as the reference traced it (one ray through the centre). */
    public Color colourAt(int x, int y) {
        int c = cell(x, y);
        int s = columns[0][c];
        return s == 0 ? background : colour(hitIndex[c], 9);
    }

    private int col(int c, int i) {
        return columns[1 + c][i];
    }

    private Color colour(int i, int c) {
        int r = col(c, i);
        int scale = c == 9 ? COLOUR_SCALE : TERM_SCALE;
        return r == NULL ? null
                : new Color(fixedVal(r, scale), fixedVal(col(c + 1, i), scale), fixedVal(col(c + 2, i), scale));
    }

    /** The 24-bit code of a distance: its float32 rounded to {@link #T_BITS} mantissa bits. */
    static int num(double v) {
        return num(v, T_BITS);
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

    /** The 24-bit code of a number in steps of 1/scale (offset, so that codes order as numbers do). */
    static int fixed(double v, int scale) {
        double q = Math.rint(v * scale);
        return OFFSET + (int) Math.max(-OFFSET, Math.min(OFFSET - 2, Double.isNaN(q) ? 0 : q));
    }

    /** The number of a fixed-point code. */
    static double fixedVal(int code, int scale) {
        return (double) (code - OFFSET) / scale;
    }

    private static void colour(int[] r, int at, Color c, int scale) {
        r[at] = c == null ? NULL : fixed(c.r, scale);
        r[at + 1] = c == null ? NULL : fixed(c.g, scale);
        r[at + 2] = c == null ? NULL : fixed(c.b, scale);
    }

    /** The surface column: deltas of its values, as three byte planes (high, middle, low). */
    private static void column(DataOutputStream out, int[] v) throws IOException {
        int[] delta = new int[v.length];
        int prev = 0;
        for (int i = 0; i < v.length; i++) {
            delta[i] = (v[i] - prev) & 0xFFFFFF;
            prev = v[i];
        }
        planes(out, delta);
    }

    private static int[] column(DataInputStream in, int n) throws IOException {
        int[] v = planes(in, n);
        int prev = 0;
        for (int i = 0; i < n; i++) {
            v[i] = (v[i] + prev) & 0xFFFFFF;
            prev = v[i];
        }
        return v;
    }

    /** 24-bit values as three byte planes (high, middle, low). */
    private static void planes(DataOutputStream out, int[] v) throws IOException {
        byte[] plane = new byte[v.length];
        for (int shift = 16; shift >= 0; shift -= 8) {
            for (int i = 0; i < v.length; i++) {
                plane[i] = (byte) (v[i] >>> shift);
            }
            out.write(plane);
        }
    }

    private static int[] planes(DataInputStream in, int n) throws IOException {
        int[] v = new int[n];
        for (int shift = 16; shift >= 0; shift -= 8) {
            byte[] plane = new byte[n];
            in.readFully(plane);
            for (int i = 0; i < n; i++) {
                v[i] |= (plane[i] & 0xFF) << shift;
            }
        }
        return v;
    }

    /** A 24-bit difference as a small number: 0, -1, 1, -2, ... become 0, 1, 2, 3, ... */
    static int zigzag(int d) {
        int s = (d << 8) >> 8; // sign-extended 24 bits
        return ((s << 1) ^ (s >> 31)) & 0xFFFFFF;
    }

    static int unzigzag(int z) {
        return (z >>> 1) ^ -(z & 1);
    }

    /**
     * The prediction both sides make of each value from the values before it: the columns are
     * coded in {@link #order} (the pixel's colour after its terms), the pixels in reading order.
     */
    private static final class Predictor {
        final int[] order;
        private final int w;
        private final int[] surf;
        /** Pixel index of every hit pixel, and hit index of every pixel (-1: none). */
        private final int[] pixel;
        private final int[] hitAt;
        /** The columns' values (the writer's, or the reader's being filled). */
        private final int[][] values;
        /** The red column of each green or blue column; -1 for the others. */
        private final int[] red;
        /** The terms summed into the colour: the first column of each of their colours. */
        private final int[] terms;
        private final int[] last;

        Predictor(int w, int h, int[] surf, int nl, int[][] values) {
            this.w = w;
            this.surf = surf;
            this.values = values;
            int cols = values.length;
            int hits = values[0].length;
            pixel = new int[hits];
            hitAt = new int[w * h];
            int n = 0;
            for (int i = 0; i < surf.length; i++) {
                hitAt[i] = surf[i] == 0 ? -1 : n;
                if (surf[i] != 0) {
                    pixel[n++] = i;
                }
            }
            red = new int[cols];
            java.util.Arrays.fill(red, -1);
            terms = new int[1 + 2 * nl];
            terms[0] = 6;
            for (int l = 0; l < nl; l++) {
                int o = HIT_COLUMNS + LIGHT_COLUMNS * l;
                terms[1 + 2 * l] = o + 3;
                terms[2 + 2 * l] = o + 6;
            }
            for (int c : terms) {
                red[c + 1] = c;
                red[c + 2] = c;
            }
            red[10] = 9;
            red[11] = 9;
            order = new int[cols];
            int k = 0;
            for (int c = 0; c < cols; c++) {
                if (c < 9 || c > 11) {
                    order[k++] = c;
                }
            }
            order[k++] = 9;
            order[k++] = 10;
            order[k] = 11;
            last = new int[cols];
        }

        /** The value of column c at hit i, on the writer's side. */
        int coded(int c, int i) {
            last[c] = values[c][i];
            return values[c][i];
        }

        /** The reader's side: keeps a decoded value. */
        void decode(int c, int i, int v) {
            values[c][i] = v;
            last[c] = v;
        }

        /** The prediction of column c at hit i, from what comes before it. */
        int predict(int c, int i) {
            if (c >= 9 && c <= 11 && values[4][i] == 1) {
                int p = sumOfTerms(c - 9, i);
                if (p >= 0) {
                    return p;
                }
            }
            if (red[c] >= 0) {
                int p = ratio(c, i);
                if (p >= 0) {
                    return p;
                }
            }
            return spatial(c, i);
        }

        /** The colour channel as the sum of the pixel's terms (in the colour's steps); -1 when it has none. */
        private int sumOfTerms(int channel, int i) {
            long sum = 0;
            boolean any = false;
            for (int t : terms) {
                int v = values[t + channel][i];
                if (v != NULL) {
                    sum += v - OFFSET;
                    any = true;
                }
            }
            if (!any) {
                return -1;
            }
            sum *= COLOUR_SCALE / TERM_SCALE;
            return (int) Math.max(0, Math.min(NULL - 1, OFFSET + sum));
        }

        /**
         * A green or blue value as this pixel's red times the ratio of a neighbour on the same
         * surface (a material's colour is a constant ratio over it); -1 when there is none to use.
         */
        private int ratio(int c, int i) {
            int r = values[red[c]][i];
            if (r == NULL) {
                return -1;
            }
            int at = pixel[i];
            int n = at % w > 0 && surf[at - 1] == surf[at] ? hitAt[at - 1]
                    : at >= w && surf[at - w] == surf[at] ? hitAt[at - w] : -1;
            if (n < 0) {
                return -1;
            }
            int nr = values[red[c]][n];
            int nv = values[c][n];
            if (nr == NULL || nv == NULL || nr - OFFSET < 16) {
                return -1;
            }
            long p = Math.round((double) (r - OFFSET) * (nv - OFFSET) / (nr - OFFSET));
            return (int) Math.max(0, Math.min(NULL - 1, OFFSET + p));
        }

        /** LOCO-I's median edge detector over the neighbours on the same surface; else the last value. */
        private int spatial(int c, int i) {
            int at = pixel[i];
            int x = at % w;
            int a = x > 0 ? neighbour(c, at, at - 1) : -1;
            int b = at >= w ? neighbour(c, at, at - w) : -1;
            if (a >= 0 && b >= 0) {
                int d = x > 0 ? neighbour(c, at, at - w - 1) : -1;
                if (d < 0) {
                    return a;
                } else if (d >= Math.max(a, b)) {
                    return Math.min(a, b);
                } else if (d <= Math.min(a, b)) {
                    return Math.max(a, b);
                }
                return a + b - d;
            }
            return a >= 0 ? a : b >= 0 ? b : last[c];
        }

        /** The value of column c at pixel n when it is on at's surface and not missing; else -1. */
        private int neighbour(int c, int at, int n) {
            if (surf[n] != surf[at]) {
                return -1;
            }
            int v = values[c][hitAt[n]];
            return v == NULL ? -1 : v;
        }
    }
}
