package raylab.inspect;

import java.io.IOException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import raylab.scene.SceneLoader;

/**
 * The planted mistakes the first difference must name, and how to run one: the buggy student file
 * is compiled alone and loaded, with the framework, in a class loader of its own (child first for
 * {@code raylab.*}), so that the render and the traces run through it as through a student's code.
 */
final class InspectCorpus {
    /**
     * One planted mistake: the buggy file (under src/test/resources/submissions/), the published
     * scene it is looked at in, the method the first difference must name and a phrase of its line.
     */
    record Bug(String file, String scene, String method, String phrase) {
        @Override
        public String toString() {
            return file + " in " + scene;
        }
    }

    /** The corpus: the five mistakes and five more of the grader's bug corpus (mistakes/corpus.json). */
    static final List<Bug> BUGS = List.of(
            new Bug("inspect/sphere-farther-root/Sphere.java", "spheres", "Sphere.intersect", "farther root"),
            new Bug("bugs1/Box.java", "boxes", "Box.intersect", "Box.intersect"),
            new Bug("bugs2/Shadows.java", "shadows", "Shadows.isShadowed", "shadow acne"),
            new Bug("bugs1/BlinnPhong.java", "highlights", "BlinnPhong.specular", "a unit vector"),
            new Bug("inspect/shading-no-ambient/Shading.java", "shadows", "Shading.shade", "leaves out the ambient term"),
            new Bug("bugs2/Shading.java", "shadows", "Shading.shade", "adds the ambient term 2 times"),
            new Bug("mistakes/triangle-normal-toward-ray/Triangle.java", "triangles", "Triangle.intersect",
                    "points into the surface"),
            new Bug("bugs2/Triangle.java", "triangles", "Triangle.intersect", "replaced the closer hit"),
            new Bug("mistakes/phong-n-dot-l/BlinnPhong.java", "highlights", "BlinnPhong.specular", "n·h"),
            new Bug("bugs3/Shadows.java", "shadows-small", "Shadows.isShadowed", "misses a blocker"));

    private InspectCorpus() {
    }

    static Path root() {
        return Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    }

    /**
     * A copy of scenes/ with the reference's traces of {@code names} (traced by the classes on the
     * class path), every pixel of each.
     */
    static Path scenesWithTraces(Path dir, List<String> names) throws Exception {
        return scenesWithTraces(dir, names, false);
    }

    /** As above; {@code asShipped}: with the release's stride ({@link TraceFile#strideFor}), as the starter has them. */
    static Path scenesWithTraces(Path dir, List<String> names, boolean asShipped) throws Exception {
        Path scenes = dir.resolve("scenes");
        copy(root().resolve("scenes"), scenes);
        for (String n : names) {
            Path json = scenes.resolve(n + ".json");
            var scene = SceneLoader.load(json);
            TraceFile.write(new Tracer(scene), TraceFile.pathFor(json),
                    asShipped ? TraceFile.strideFor(scene.width, scene.height) : 1);
        }
        return scenes;
    }

    /** scenes/, scenes/reference/ and scenes/meshes/ (the folders a scene and its image read), file by file. */
    static void copy(Path from, Path to) throws IOException {
        for (String sub : List.of("", "reference", "meshes")) {
            Path d = to.resolve(sub);
            Files.createDirectories(d);
            try (var files = Files.list(from.resolve(sub))) {
                for (Path f : files.filter(Files::isRegularFile).toList()) {
                    Files.copy(f, d.resolve(f.getFileName().toString()));
                }
            }
        }
    }

    /** The buggy file compiled into {@code out}; an AssertionError with javac's messages if it does not compile. */
    static Path compile(String file, Path out) throws IOException {
        Files.createDirectories(out);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        java.io.StringWriter errors = new java.io.StringWriter();
        var fm = javac.getStandardFileManager(null, null, null);
        boolean ok = javac.getTask(errors, fm, null, List.of("-d", out.toString(), "-cp",
                System.getProperty("java.class.path"), "--release", "17", "-nowarn"), null,
                fm.getJavaFileObjects(root().resolve("src/test/resources/submissions").resolve(file).toFile())).call();
        if (!ok) {
            throw new AssertionError(file + " does not compile: " + errors);
        }
        return out;
    }

    /** A loader that takes raylab.* from {@code student} first, then from the framework's classes. */
    static URLClassLoader loader(Path student) throws IOException {
        List<URL> urls = new ArrayList<>();
        if (student != null) {
            urls.add(student.toUri().toURL());
        }
        for (String e : System.getProperty("java.class.path").split(java.io.File.pathSeparator)) {
            if (e.endsWith("classes") && !e.endsWith("test-classes")) {
                urls.add(Path.of(e).toUri().toURL());
            }
        }
        return new URLClassLoader(urls.toArray(URL[]::new), InspectCorpus.class.getClassLoader()) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
                synchronized (getClassLoadingLock(name)) {
                    if (!name.startsWith("raylab.")) {
                        return super.loadClass(name, resolve);
                    }
                    Class<?> c = findLoadedClass(name);
                    if (c == null) {
                        c = findClass(name);
                    }
                    if (resolve) {
                        resolveClass(c);
                    }
                    return c;
                }
            }
        };
    }

    /** What the worst pixel shows: {x, y, method, line}, or null when no traced pixel differs. */
    static String[] worst(ClassLoader loader, Path sceneJson) throws Exception {
        Class<?> in = loader.loadClass("raylab.inspect.Inspection");
        Object inspection = in.getMethod("of", Path.class).invoke(null, sceneJson);
        Object image = in.getMethod("render", int.class).invoke(inspection, 1);
        Optional<?> f = (Optional<?>) in.getMethod("worst", java.awt.image.BufferedImage.class).invoke(inspection, image);
        if (f.isEmpty()) {
            return null;
        }
        Object finding = f.get();
        Object d = call(finding, "difference");
        return new String[] {String.valueOf(call(finding, "x")), String.valueOf(call(finding, "y")),
            (String) call(d, "method"), (String) call(d, "line")};
    }

    static Object call(Object o, String name) throws Exception {
        Method m = o.getClass().getMethod(name);
        m.setAccessible(true);
        return m.invoke(o);
    }

    public static void main(String[] args) throws Exception {
        Path dir = Files.createTempDirectory("inspect-corpus");
        Path scenes = scenesWithTraces(dir, BUGS.stream().map(Bug::scene).distinct().toList());
        for (Bug b : BUGS) {
            Path classes = compile(b.file(), dir.resolve("bug" + BUGS.indexOf(b)));
            try (URLClassLoader l = loader(classes)) {
                String[] w = worst(l, scenes.resolve(b.scene() + ".json"));
                System.out.println(b + " -> " + (w == null ? "nothing" : String.join(" | ", w)));
            }
        }
    }
}
