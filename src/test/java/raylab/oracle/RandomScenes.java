package raylab.oracle;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import raylab.scene.Scene;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;

/**
 * Seeded random scenes in the scene file format, built to reach the corners where a render plan
 * shortcut or a convention could go wrong: the camera inside a sphere or a box, lights inside,
 * exactly on and just off surfaces, lights with and without shadows, a single convex surface,
 * nested and touching surfaces, meshes, orthographic and perspective cameras, and scales from
 * 1e-3 to 1e4 (sometimes far from the origin).
 *
 * <p>Each scene is JSON text (plus an OBJ file when it has a mesh), loaded with
 * {@link SceneLoader}, so a failing scene can be written out and rendered with
 * {@code ./raylab render}. The number of scenes a test runs is {@link #count()}: 300 by default,
 * {@code -Dscenes=N} for long runs.
 */
public final class RandomScenes {
    /** Small images keep {@code ./mvnw verify} fast. */
    public static final int WIDTH = 24;
    public static final int HEIGHT = 18;
    /** Where scenes with meshes are written to be loaded, and where failing scenes go. */
    public static final Path WORK = Path.of("target", "random-scenes");
    public static final Path FAILING = Path.of("target", "failing-scenes");

    private RandomScenes() {
    }

    /** The number of scenes per test: {@code -Dscenes=N}, default 300. */
    public static int count() {
        return Integer.getInteger("scenes", 300);
    }

    /** The seeds a test runs: 1 .. count(), or just {@code -Dseed=S} to replay one scene. */
    public static List<Long> seeds() {
        String one = System.getProperty("seed");
        List<Long> out = new ArrayList<>();
        if (one != null && !one.isBlank()) {
            out.add(Long.parseLong(one.trim()));
            return out;
        }
        for (long s = 1; s <= count(); s++) {
            out.add(s);
        }
        return out;
    }

    /** A generated scene: its JSON, the OBJ text of its mesh (or null) and what it exercises. */
    public record Generated(long seed, String json, String obj, String summary) {
        /** The file name of the mesh, relative to the scene file. */
        public String objName() {
            return "seed-" + seed + ".obj";
        }

        /** Loads the scene (writing the mesh next to it first). */
        public Scene load() {
            try {
                Files.createDirectories(WORK);
                Path file = WORK.resolve("seed-" + seed + ".json");
                if (obj != null) {
                    Files.writeString(WORK.resolve(objName()), obj);
                }
                return SceneLoader.parse(json, file);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } catch (SceneException e) {
                throw new IllegalStateException("generated scene " + seed + " does not load: " + e.getMessage()
                        + "\n" + json, e);
            }
        }

        /** Writes the scene (and its mesh) to target/failing-scenes/ and returns the JSON's path. */
        public Path writeFailing() {
            try {
                Files.createDirectories(FAILING);
                if (obj != null) {
                    Files.writeString(FAILING.resolve(objName()), obj);
                }
                Path file = FAILING.resolve("seed-" + seed + ".json");
                Files.writeString(file, json);
                return file;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }

        /** One line for failure messages: seed, file, how to render it. */
        public String describe() {
            Path file = writeFailing();
            return "scene seed " + seed + " (" + summary + "), written to " + file
                    + "\n  render it: ./raylab render " + file + "   (and with --brute-force)"
                    + "\n  replay the test on it alone: -Dseed=" + seed;
        }
    }

    /** One solid of the scene, kept to place the camera and lights inside, on or near it. */
    private record Solid(boolean sphere, double[] a, double[] b) {
        // sphere: a = centre, b = {radius}; box: a = min, b = max
    }

    /** The scene of the given seed. */
    public static Generated generate(long seed) {
        return new Builder(seed).build();
    }

    private static final class Builder {
        final long seed;
        final SplittableRandom rnd;
        final double scale;
        final double[] origin;
        final List<Solid> solids = new ArrayList<>();
        final List<String> surfaces = new ArrayList<>();
        final List<String> lights = new ArrayList<>();
        final List<String> notes = new ArrayList<>();
        String obj;

        Builder(long seed) {
            this.seed = seed;
            this.rnd = new SplittableRandom(seed * 0x9E3779B97F4A7C15L + 12345);
            this.scale = Math.pow(10, rnd.nextDouble(-3, 4));
            boolean far = rnd.nextInt(4) == 0;
            this.origin = far ? new double[] {s(rnd.nextDouble(-40, 40)), s(rnd.nextDouble(-40, 40)),
                s(rnd.nextDouble(-40, 40))} : new double[] {0, 0, 0};
            notes.add(String.format(Locale.ROOT, "scale %.3g%s", scale, far ? ", far from the origin" : ""));
        }

        double s(double v) {
            return v * scale;
        }

        /** A point of the scene: origin + scale·(x, y, z). */
        double[] at(double x, double y, double z) {
            return new double[] {origin[0] + s(x), origin[1] + s(y), origin[2] + s(z)};
        }

        double u(double lo, double hi) {
            return rnd.nextDouble(lo, hi);
        }

        Generated build() {
            int kind = rnd.nextInt(7);
            switch (kind) {
                case 0 -> {
                    notes.add("single sphere");
                    sphere(at(u(-1, 1), u(-1, 1), u(-1, 1)), s(u(0.5, 2)));
                }
                case 1 -> {
                    notes.add("single box");
                    double[] c = at(u(-1, 1), u(-1, 1), u(-1, 1));
                    box(c, new double[] {s(u(0.3, 2)), s(u(0.3, 2)), s(u(0.3, 2))});
                }
                case 2 -> {
                    notes.add("nested solids");
                    double[] c = at(u(-0.5, 0.5), u(-0.5, 0.5), u(-0.5, 0.5));
                    double r = s(u(1, 2));
                    boolean sphereOutside = rnd.nextBoolean();
                    if (sphereOutside) {
                        sphere(c, 2.5 * r);
                        box(c, new double[] {r * u(0.3, 0.9), r * u(0.3, 0.9), r * u(0.3, 0.9)});
                    } else {
                        box(c, new double[] {2.5 * r, 2.5 * r, 2.5 * r});
                        sphere(c, r * u(0.4, 1));
                    }
                }
                case 3 -> {
                    notes.add("touching solids on a floor");
                    floor();
                    double r = s(u(0.4, 1));
                    double[] c = at(u(-1, 1), 0, u(-1, 1));
                    c[1] = origin[1] + r; // resting on the floor (whose top is origin y)
                    sphere(c, r);
                    double[] m = at(u(0.5, 2), 0, u(-1, 1));
                    double[] half = {s(u(0.2, 0.8)), s(u(0.2, 0.8)), s(u(0.2, 0.8))};
                    m[1] = origin[1] + half[1];
                    double[] min = {m[0] - half[0], origin[1], m[2] - half[2]};
                    double[] max = {m[0] + half[0], origin[1] + 2 * half[1], m[2] + half[2]};
                    boxMinMax(min, max); // stands on the floor: bottom face on the floor's top face
                    if (rnd.nextBoolean()) { // a second box touching the first one's side
                        boxMinMax(new double[] {max[0], origin[1], min[2]},
                                new double[] {max[0] + s(u(0.2, 0.6)), origin[1] + s(u(0.2, 1)), max[2]});
                    }
                }
                case 4 -> {
                    notes.add("mesh");
                    mesh();
                    if (rnd.nextBoolean()) {
                        floor();
                    }
                }
                default -> {
                    notes.add("mixed");
                    int n = 2 + rnd.nextInt(6);
                    for (int i = 0; i < n; i++) {
                        double[] c = at(u(-3, 3), u(-3, 3), u(-3, 3));
                        switch (rnd.nextInt(3)) {
                            case 0 -> sphere(c, s(u(0.2, 1.5)));
                            case 1 -> box(c, new double[] {s(u(0.1, 1.5)), s(u(0.1, 1.5)), s(u(0.1, 1.5))});
                            default -> triangle(c);
                        }
                    }
                    if (rnd.nextInt(3) == 0) {
                        floor();
                    }
                }
            }
            if (solids.isEmpty()) {
                sphere(at(u(-1, 1), u(-1, 1), u(-1, 1)), s(u(0.5, 2)));
            }
            int nLights = rnd.nextInt(4); // 0 .. 3
            for (int i = 0; i < nLights; i++) {
                light(i);
            }
            String camera = camera();
            StringBuilder j = new StringBuilder();
            j.append("{\n  \"image\": {\"width\": ").append(WIDTH).append(", \"height\": ").append(HEIGHT)
                    .append("},\n  \"camera\": ").append(camera).append(",\n");
            if (rnd.nextInt(3) > 0) {
                j.append("  \"background\": ").append(color(0, 0.3)).append(",\n");
            }
            if (rnd.nextInt(3) > 0) {
                j.append("  \"ambient\": ").append(color(0, 0.3)).append(",\n");
            }
            String effects = effects();
            if (!effects.isEmpty()) {
                j.append("  \"effects\": {").append(effects).append("},\n");
            }
            j.append("  \"materials\": {\n").append(materials()).append("\n  },\n");
            j.append("  \"surfaces\": [\n    ").append(String.join(",\n    ", surfaces)).append("\n  ],\n");
            j.append("  \"lights\": [").append(lights.isEmpty() ? "" : "\n    " + String.join(",\n    ", lights) + "\n  ")
                    .append("]\n}\n");
            return new Generated(seed, j.toString(), obj, String.join(", ", notes));
        }

        static final String[] MATERIALS = {"m0", "m1", "m2", "m3", "m4"};

        String material() {
            // m0..m2 lit (Lambertian, Blinn-Phong, Blinn-Phong with ks = 0), m3 flat, m4 normals;
            // lit ones are much more likely.
            int k = rnd.nextInt(10);
            return k < 4 ? "m0" : k < 7 ? "m1" : k < 8 ? "m2" : k < 9 ? "m3" : "m4";
        }

        String materials() {
            List<String> m = new ArrayList<>();
            m.add("    \"m0\": {\"type\": \"lambertian\", \"kd\": " + color(0.1, 1)
                    + (rnd.nextInt(3) == 0 ? ", \"ka\": " + (rnd.nextBoolean() ? "0" : color(0, 1)) : "") + "}");
            m.add("    \"m1\": {\"type\": \"blinnPhong\", \"kd\": " + color(0, 0.8) + ", \"ks\": " + color(0.1, 0.8)
                    + ", \"p\": " + num(rnd.nextInt(4) == 0 ? 0 : Math.pow(2, u(0, 8))) + "}");
            m.add("    \"m2\": {\"type\": \"blinnPhong\", \"kd\": " + color(0.1, 0.8) + ", \"ks\": 0, \"p\": 30, \"ka\": 0}");
            m.add("    \"m3\": {\"type\": \"flat\", \"color\": " + color(0, 1) + "}");
            m.add("    \"m4\": {\"type\": \"normals\"}");
            return String.join(",\n", m);
        }

        String effects() {
            List<String> e = new ArrayList<>();
            for (String name : new String[] {"shadows", "specular", "ambient", "acceleration"}) {
                int k = rnd.nextInt(8);
                if (k == 0) {
                    e.add("\"" + name + "\": false");
                } else if (k == 1) {
                    e.add("\"" + name + "\": true");
                }
            }
            return String.join(", ", e);
        }

        void sphere(double[] c, double r) {
            solids.add(new Solid(true, c, new double[] {r}));
            surfaces.add("{\"type\": \"sphere\", \"center\": " + vec(c) + ", \"radius\": " + num(r)
                    + ", \"material\": \"" + material() + "\"}");
        }

        void box(double[] c, double[] half) {
            boxMinMax(new double[] {c[0] - half[0], c[1] - half[1], c[2] - half[2]},
                    new double[] {c[0] + half[0], c[1] + half[1], c[2] + half[2]});
        }

        void boxMinMax(double[] min, double[] max) {
            solids.add(new Solid(false, min, max));
            surfaces.add("{\"type\": \"box\", \"min\": " + vec(min) + ", \"max\": " + vec(max)
                    + ", \"material\": \"" + material() + "\"}");
        }

        /** A floor box whose top face is the plane y = origin y. */
        void floor() {
            boxMinMax(at(-8, -0.5, -8), new double[] {origin[0] + s(8), origin[1], origin[2] + s(8)});
        }

        void triangle(double[] c) {
            double[][] v = new double[3][];
            for (int i = 0; i < 3; i++) {
                v[i] = new double[] {c[0] + s(u(-1.5, 1.5)), c[1] + s(u(-1.5, 1.5)), c[2] + s(u(-1.5, 1.5))};
            }
            surfaces.add("{\"type\": \"triangle\", \"vertices\": [" + vec(v[0]) + ", " + vec(v[1]) + ", " + vec(v[2])
                    + "], \"material\": \"" + material() + "\"}");
        }

        /** A closed octahedron or an open folded sheet of triangles sharing edges. */
        void mesh() {
            StringBuilder o = new StringBuilder("# random mesh, seed " + seed + "\n");
            if (rnd.nextBoolean()) {
                notes.add("octahedron");
                double[][] v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
                for (double[] p : v) {
                    o.append(String.format(Locale.ROOT, "v %s %s %s%n", num(p[0] * u(0.7, 1.3)),
                            num(p[1] * u(0.7, 1.3)), num(p[2] * u(0.7, 1.3))));
                }
                int[][] f = {{1, 3, 5}, {3, 2, 5}, {2, 4, 5}, {4, 1, 5}, {3, 1, 6}, {2, 3, 6}, {4, 2, 6}, {1, 4, 6}};
                for (int[] t : f) {
                    o.append("f ").append(t[0]).append(' ').append(t[1]).append(' ').append(t[2]).append('\n');
                }
            } else {
                notes.add("folded sheet");
                int k = 3 + rnd.nextInt(4);
                for (int i = 0; i <= k; i++) {
                    for (int jj = 0; jj <= k; jj++) {
                        double x = -1 + 2.0 * i / k;
                        double z = -1 + 2.0 * jj / k;
                        double y = 0.4 * Math.sin(3 * x + u(0, 0.3)) * Math.cos(2 * z);
                        o.append(String.format(Locale.ROOT, "v %s %s %s%n", num(x), num(y), num(z)));
                    }
                }
                for (int i = 0; i < k; i++) {
                    for (int jj = 0; jj < k; jj++) {
                        int a = i * (k + 1) + jj + 1;
                        int b = a + 1;
                        int c = a + k + 1;
                        int d = c + 1;
                        o.append("f ").append(a).append(' ').append(b).append(' ').append(d).append('\n');
                        o.append("f ").append(a).append(' ').append(d).append(' ').append(c).append('\n');
                    }
                }
            }
            obj = o.toString();
            double size = s(u(0.8, 2));
            // The octahedron's inside is reachable: a solid for camera and light placement.
            solids.add(new Solid(false, new double[] {origin[0] - 0.3 * size, origin[1] - 0.3 * size,
                origin[2] - 0.3 * size}, new double[] {origin[0] + 0.3 * size, origin[1] + 0.3 * size,
                origin[2] + 0.3 * size}));
            surfaces.add("{\"type\": \"mesh\", \"file\": \"seed-" + seed + ".obj\", \"scale\": " + num(size)
                    + ", \"translate\": " + vec(origin) + ", \"material\": \"" + material() + "\"}");
        }

        Solid anySolid() {
            return solids.get(rnd.nextInt(solids.size()));
        }

        /** A point strictly inside a solid, away from its surface. */
        double[] inside(Solid s) {
            if (s.sphere) {
                double[] d = unit();
                double r = s.b[0] * u(0, 0.8);
                return new double[] {s.a[0] + d[0] * r, s.a[1] + d[1] * r, s.a[2] + d[2] * r};
            }
            double[] p = new double[3];
            for (int i = 0; i < 3; i++) {
                double lo = s.a[i];
                double hi = s.b[i];
                p[i] = lo + (hi - lo) * u(0.1, 0.9);
            }
            return p;
        }

        /**
         * A point on the surface of a solid, shifted by {@code off} times its size along the
         * outward normal (0: exactly on a box face; spheres can only be approached).
         */
        double[] onSurface(Solid s, double off) {
            if (s.sphere) {
                double[] d = unit();
                double r = s.b[0] * (1 + off);
                return new double[] {s.a[0] + d[0] * r, s.a[1] + d[1] * r, s.a[2] + d[2] * r};
            }
            double[] p = inside(s);
            int axis = rnd.nextInt(3);
            boolean high = rnd.nextBoolean();
            double size = s.b[axis] - s.a[axis];
            p[axis] = high ? s.b[axis] + off * Math.max(size, scale) : s.a[axis] - off * Math.max(size, scale);
            return p;
        }

        double[] unit() {
            while (true) {
                double[] v = {u(-1, 1), u(-1, 1), u(-1, 1)};
                double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                if (l > 0.1 && l <= 1) {
                    return new double[] {v[0] / l, v[1] / l, v[2] / l};
                }
            }
        }

        void light(int i) {
            double[] p;
            String where;
            int k = rnd.nextInt(10);
            if (k < 4) {
                p = at(u(-6, 6), u(1, 8), u(-6, 6));
                where = "outside";
            } else if (k < 6) {
                p = inside(anySolid());
                where = "inside a surface";
            } else if (k < 8) {
                Solid s = anySolid();
                if (s.sphere) {
                    p = onSurface(s, (rnd.nextBoolean() ? 1 : -1) * 1e-7);
                    where = "just off a sphere";
                } else {
                    p = onSurface(s, 0);
                    where = "on a box face";
                }
            } else {
                p = onSurface(anySolid(), (rnd.nextBoolean() ? 1 : -1) * Math.pow(10, u(-7, -3)));
                where = "just off a surface";
            }
            boolean shadows = rnd.nextInt(4) > 0;
            notes.add("light " + where + (shadows ? "" : " (no shadows)"));
            lights.add("{\"type\": \"point\", \"name\": \"light " + i + " " + where + "\", \"position\": " + vec(p)
                    + ", \"intensity\": " + color(0.2, 1.2) + (shadows ? "" : ", \"shadows\": false") + "}");
        }

        String camera() {
            double[] eye;
            double[] look;
            int k = rnd.nextInt(10);
            if (k < 3) {
                Solid s = anySolid();
                eye = inside(s);
                look = new double[] {eye[0] + u(-1, 1), eye[1] + u(-1, 1), eye[2] + u(-1, 1)};
                notes.add("camera inside a " + (s.sphere ? "sphere" : "box"));
            } else {
                double[] d = unit();
                double dist = s(u(3, 10));
                eye = new double[] {origin[0] + d[0] * dist, origin[1] + Math.abs(d[1]) * dist, origin[2] + d[2] * dist};
                look = at(u(-0.5, 0.5), u(-0.5, 0.5), u(-0.5, 0.5));
            }
            double[] dir = {look[0] - eye[0], look[1] - eye[1], look[2] - eye[2]};
            if (Math.abs(dir[0]) + Math.abs(dir[2]) < 1e-3 * (Math.abs(dir[1]) + 1e-300)) {
                dir[0] += 0.1 * Math.abs(dir[1]);
            }
            String up = "[0, 1, 0]";
            if (rnd.nextInt(2) == 0) {
                notes.add("orthographic");
                return "{\"type\": \"orthographic\", \"eye\": " + vec(eye) + ", \"viewDirection\": " + vec(dir)
                        + ", \"up\": " + up + ", \"viewHeight\": " + num(s(u(1, 8))) + "}";
            }
            notes.add("perspective");
            return "{\"type\": \"perspective\", \"eye\": " + vec(eye) + ", \"viewDirection\": " + vec(dir)
                    + ", \"up\": " + up + ", \"fov\": " + num(u(20, 120)) + "}";
        }

        String color(double lo, double hi) {
            return "[" + num(u(lo, hi)) + ", " + num(u(lo, hi)) + ", " + num(u(lo, hi)) + "]";
        }

        static String vec(double[] v) {
            return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]";
        }

        /** Exact: Double.toString round-trips, and its form (1.0E-3) is valid JSON. */
        static String num(double v) {
            return Double.toString(v);
        }
    }
}
