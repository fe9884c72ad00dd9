package raylab.inspect;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.net.URI;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

/**
 * The inspect page in a real browser (headless chromium, as BrowserReportTest): for the correct code
 * and for the issue's planted mistakes (wrong root, inward normal, acne, unnormalised half vector,
 * missing ambient) the page is served from the student's classes, a click on a pixel (a MouseEvent
 * dispatched at the pixel's place on the student's picture, through the page's own click handler)
 * shows both ray trees, and the first difference shown names the planted mistake.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class InspectBrowserTest {
    @TempDir
    static Path dir;
    Path scenes;
    String chromium;

    @BeforeAll
    void setUp() throws Exception {
        for (String c : List.of("chromium", "chromium-browser", "google-chrome")) {
            for (String d : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
                if (chromium == null && Files.isExecutable(Path.of(d, c))) {
                    chromium = Path.of(d, c).toString();
                }
            }
        }
        if (chromium == null) {
            if (System.getenv("RAYLAB_REQUIRE_CHROMIUM") != null) {
                throw new AssertionError("RAYLAB_REQUIRE_CHROMIUM is set but no chromium is on the PATH");
            }
            Assumptions.abort("no chromium on the PATH (apt-get install -y chromium); .ci/run installs it");
        }
        scenes = InspectCorpus.scenesWithTraces(dir, List.of("spheres", "boxes-lamp", "shadows", "highlights"));
    }

    /** Serves the page from {@code loader}'s classes, clicks pixel (x, y) in chromium: {difference, method, shown, rows}. */
    String[] click(ClassLoader loader, String scene, int x, int y) throws Exception {
        Class<?> in = loader.loadClass("raylab.inspect.Inspection");
        Object inspection = in.getMethod("of", Path.class).invoke(null, scenes.resolve(scene + ".json"));
        Object mine = in.getMethod("render", int.class).invoke(inspection, 1);
        Class<?> pageClass = loader.loadClass("raylab.inspect.InspectPage");
        Object page = pageClass.getConstructor(in, java.awt.image.BufferedImage.class, String.class, Function.class)
                .newInstance(inspection, mine, scene, (Function<Throwable, String>) String::valueOf);
        URI uri = (URI) pageClass.getMethod("start", int.class).invoke(page, 0);
        try {
            Path profile = Files.createTempDirectory(dir, "profile");
            List<String> cmd = List.of(chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                    "--disable-background-networking", "--disable-component-update", "--disable-sync",
                    "--user-data-dir=" + profile, "--window-size=1280,900", "--virtual-time-budget=8000", "--dump-dom",
                    uri + "#" + x + "," + y);
            Process p = new ProcessBuilder(cmd).redirectError(dir.resolve("chromium.err").toFile()).start();
            p.getOutputStream().close();
            String dom = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "chromium finished");
            Matcher d = Pattern.compile("<div id=\"difference\" data-method=\"([^\"]*)\">([^<]*)</div>").matcher(dom);
            Matcher shown = Pattern.compile("data-shown=\"(\\d+,\\d+)\"").matcher(dom);
            assertTrue(d.find() && shown.find(), () -> "the page showed a pixel's trees: " + tail(dom));
            Matcher rows = Pattern.compile("<tr class=\"(first|differs|same)\">").matcher(dom);
            int n = 0;
            while (rows.find()) {
                n++;
            }
            return new String[] {d.group(2).replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"), d.group(1),
                shown.group(1), Integer.toString(n)};
        } finally {
            pageClass.getMethod("stop").invoke(page);
        }
    }

    private static String tail(String s) {
        return s.length() < 3000 ? s : s.substring(s.length() - 3000);
    }

    /** A pixel whose reference hit is a surface of this kind. */
    int[] pixelOn(String scene, String kind) throws Exception {
        var s = raylab.scene.SceneLoader.load(scenes.resolve(scene + ".json"));
        TraceFile f = TraceFile.read(TraceFile.pathFor(scenes.resolve(scene + ".json")), s);
        for (int y = s.height / 2; y < s.height; y++) {
            for (int x = s.width / 4; x < s.width; x++) {
                RayTree t = f.tree(x, y);
                if (t.hit() && kind.equals(t.kind) && t.lit) {
                    return new int[] {x, y};
                }
            }
        }
        throw new AssertionError("no pixel on a " + kind + " in " + scene);
    }

    void planted(String file, String scene, int[] pixel, String method, String phrase) throws Exception {
        Path classes = InspectCorpus.compile(file, dir.resolve("c" + Math.abs(file.hashCode())));
        try (URLClassLoader l = InspectCorpus.loader(classes)) {
            int[] at = pixel;
            if (at == null) {
                String[] w = InspectCorpus.worst(l, scenes.resolve(scene + ".json"));
                assertTrue(w != null, file + ": a worst pixel with a difference");
                at = new int[] {Integer.parseInt(w[0]), Integer.parseInt(w[1])};
            }
            String[] r = click(l, scene, at[0], at[1]);
            String where = file + " in " + scene + " at (" + at[0] + ", " + at[1] + ")";
            System.out.println(where + " -> " + r[0]);
            assertTrue(r[2].equals(at[0] + "," + at[1]), where + ": expected the clicked pixel's trees, shown: " + r[2]);
            assertTrue(r[1].equals(method) && r[0].contains(phrase), where + ": expected " + method + " and '" + phrase
                    + "', the page shows " + r[1] + ": " + r[0]);
            assertTrue(Integer.parseInt(r[3]) >= 4, where + ": expected both trees row by row, rows: " + r[3]);
        }
    }

    @Test
    void correctCodeShowsNoDifference() throws Exception {
        try (URLClassLoader l = InspectCorpus.loader(null)) {
            String[] r = click(l, "shadows", 200, 200);
            assertTrue(r[0].startsWith("no difference") && r[1].isEmpty(), "expected no difference, shown: " + r[0]);
            assertTrue(r[2].equals("200,200"), "the clicked pixel: " + r[2]);
        }
    }

    @Test
    void wrongRoot() throws Exception {
        planted("inspect/sphere-farther-root/Sphere.java", "spheres", null, "Sphere.intersect", "farther root");
    }

    @Test
    void inwardNormal() throws Exception {
        planted("mistakes/box-normal-sign/Box.java", "boxes-lamp", pixelOn("boxes-lamp", "Box"), "Box.intersect",
                "points into the surface");
    }

    @Test
    void acne() throws Exception {
        planted("bugs2/Shadows.java", "shadows", null, "Shadows.isShadowed", "shadow acne");
    }

    @Test
    void unnormalisedHalfVector() throws Exception {
        planted("bugs1/BlinnPhong.java", "highlights", null, "BlinnPhong.specular", "unit vector");
    }

    @Test
    void missingAmbient() throws Exception {
        planted("inspect/shading-no-ambient/Shading.java", "shadows", null, "Shading.shade", "leaves out the ambient");
    }
}
