package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.grade.GradeReport.Kind;
import raylab.render.ImageCompare;
import raylab.render.PngFiles;

/**
 * The reports in a real browser (Debian's headless chromium, which .ci/run installs): the page
 * loads, every image decodes (naturalWidth &gt; 0) and nothing reaches past the right edge of a
 * 1280-pixel-wide window, for the students' Gradescope output and the instructors' report.html.
 * A script added to the page writes what it measured into the DOM, which chromium prints with
 * --dump-dom. Skipped, with the reason, only when no chromium can be found and
 * RAYLAB_REQUIRE_CHROMIUM is not set (.ci/run sets it, so CI cannot skip it).
 */
class BrowserReportTest {
    static String chromium;

    @TempDir
    Path dir;

    @BeforeAll
    static void findChromium() {
        for (String c : List.of("chromium", "chromium-browser", "google-chrome")) {
            for (String d : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
                if (Files.isExecutable(Path.of(d, c))) {
                    chromium = Path.of(d, c).toString();
                    return;
                }
            }
        }
        if (System.getenv("RAYLAB_REQUIRE_CHROMIUM") != null) {
            throw new AssertionError("RAYLAB_REQUIRE_CHROMIUM is set but no chromium is on the PATH"
                    + " (.ci/run installs it with apt-get install -y chromium)");
        }
        Assumptions.abort("no chromium on the PATH (apt-get install -y chromium); .ci/run installs it");
    }

    private static final String PROBE = """
            <script>
            window.addEventListener('load', function () {
              var imgs = Array.prototype.slice.call(document.images);
              var broken = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); }).length;
              var over = [];
              document.querySelectorAll('body *').forEach(function (e) {
                var r = e.getBoundingClientRect();
                if (r.right > window.innerWidth + 0.5) { over.push(e.tagName + ':' + Math.round(r.right)); }
              });
              var fix = document.getElementById('fix-first');
              var items = fix ? fix.querySelectorAll('li') : [];
              var links = fix ? Array.prototype.slice.call(fix.querySelectorAll('a[href^="#"]')) : [];
              var dangling = links.filter(function (a) { return !document.getElementById(a.getAttribute('href').substring(1)); }).length;
              var firstImg = document.images.length ? document.images[0].getBoundingClientRect().top : 1e9;
              var out = document.createElement('pre');
              out.id = 'raylab-probe';
              out.textContent = 'images=' + imgs.length + ' broken=' + broken + ' width=' + window.innerWidth
                  + ' scrollWidth=' + document.documentElement.scrollWidth + ' over=' + over.length + ' ' + over.slice(0, 5).join(',')
                  + ' fix=' + items.length + ' dangling=' + dangling
                  + ' fixTop=' + (fix ? Math.round(fix.getBoundingClientRect().top) : -1)
                  + ' fixBeforeImages=' + (fix ? (fix.getBoundingClientRect().bottom <= firstImg) : false)
                  + ' fixText=' + (fix ? JSON.stringify(fix.textContent) : '""');
              document.body.appendChild(out);
            });
            </script>
            """;

    private static byte[] png(BufferedImage img) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(img, "png", b);
        return b.toByteArray();
    }

    /** A report with a wrong scene, a matching one, failures with long unbroken lines, ignored files. */
    static GradeReport sample() throws IOException {
        BufferedImage ref = PngFiles.read(Path.of("scenes/reference/showcase.png"));
        BufferedImage mine = new BufferedImage(ref.getWidth(), ref.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < ref.getHeight(); y++) {
            for (int x = 0; x < ref.getWidth(); x++) {
                mine.setRGB(x, y, x < ref.getWidth() / 3 ? ref.getRGB(x, y) ^ 0x3f3f3f : ref.getRGB(x, y));
            }
        }
        ImageCompare.Result c = ImageCompare.compare(mine, ref);
        String metric = c.summary() + "; allowed: 0.500%";
        GradeReport.Images wrong = new GradeReport.Images(png(mine), png(ref), png(c.diff()), metric);
        BufferedImage small = PngFiles.read(Path.of("scenes/reference/sphere.png"));
        ImageCompare.Result same = ImageCompare.compare(small, small);
        GradeReport.Images right = new GradeReport.Images(png(small), png(small), png(same.diff()),
                same.summary() + "; allowed: 0.200%");
        String longLine = "x".repeat(400);
        List<GradeReport.Test> tests = new ArrayList<>();
        tests.add(new GradeReport.Test("phong", "specular term at n.h = 1 is ks * I", Kind.VISIBLE, 0.5, 0, false,
                "wrong colour\n  expected: rgb(1, 1, 1)\n  got:      rgb(0.5, 0.5, 0.5)\n  path: " + longLine
                        + "\nHINT: the half vector must be normalized", "printed " + longLine, "visible", 3,
                "src/test/java/raylab/material/BlinnPhongTest.java", null));
        tests.add(new GradeReport.Test("phong", "hidden one", Kind.HIDDEN, 0.5, 0, false, "secret message", "",
                "after_due_date", 3, "grader/tests/x.java", null));
        tests.add(new GradeReport.Test("phong", "a passing test with a note", Kind.VISIBLE, 0.5, 0.5, true, "", "",
                "visible", 3, "src/test/java/raylab/material/BlinnPhongTest.java", null)
                .withNote("your loop traced 2 shadow rays the plan could skip"));
        tests.add(new GradeReport.Test("phong", "data case: a wrong case", Kind.CASE, 0.25, 0, false,
                "expected a hit at t = 2 but intersect returned false", "", "visible", 3, "cases/x.json", null));
        tests.add(new GradeReport.Test("phong", "scenes/showcase.json", Kind.SCENE, 3, 0, false,
                "the image differs from the reference: " + metric, "", "visible", 300, "scenes/showcase.json", wrong));
        tests.add(new GradeReport.Test("phong", "scenes/sphere.json", Kind.SCENE, 2, 2, true, "", "", "visible", 100,
                "scenes/sphere.json", right));
        GradeReport.Milestone m = new GradeReport.Milestone("phong", "Blinn-Phong specular shading", List.of(), tests);
        List<String> ignored = new ArrayList<>();
        for (int i = 0; i < 190; i++) {
            ignored.add("src/main/java/raylab/some/very/long/path/File" + i + ".java: not a file of the assignments");
        }
        return new GradeReport(List.of(m), List.of("src/main/java/raylab/material/BlinnPhong.java <- BlinnPhong.java"),
                ignored, List.of(), 12.3);
    }

    private String probe(String html, String name) throws IOException, InterruptedException {
        String page = html.contains("</body>") ? html.replace("</body>", PROBE + "</body>")
                : "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head><body>" + html + PROBE + "</body></html>";
        Path file = dir.resolve(name);
        Files.writeString(file, page, StandardCharsets.UTF_8);
        Path profile = Files.createTempDirectory(dir, "profile");
        List<String> cmd = List.of(chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--user-data-dir=" + profile, "--window-size=1280,900", "--hide-scrollbars",
                "--virtual-time-budget=5000", "--dump-dom", file.toUri().toString());
        Process p = new ProcessBuilder(cmd).redirectError(dir.resolve(name + ".err").toFile()).start();
        p.getOutputStream().close();
        String dom = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "chromium finished");
        Matcher m = Pattern.compile("<pre id=\"raylab-probe\">([^<]*)</pre>").matcher(dom);
        assertTrue(m.find(), () -> "the probe ran (exit " + p.exitValue() + "): " + tail(dom) + "\n" + read(dir.resolve(name + ".err")));
        return m.group(1);
    }

    private static String read(Path p) {
        try {
            return tail(Files.readString(p));
        } catch (IOException e) {
            return "";
        }
    }

    private static String tail(String s) {
        return s.length() < 2000 ? s : s.substring(s.length() - 2000);
    }

    @Test
    void studentOutputLoadsDecodesAndFitsIn1280Pixels() throws Exception {
        GradeReport r = sample();
        String html = HtmlReport.forStudents(r);
        String result = probe(html, "student.html");
        System.out.println("students' output: " + result + " (" + html.length() + " characters)");
        // The differing scene's 3 images and legend, the matching scene's render and reference (folded, small).
        assertTrue(result.startsWith("images=6 broken=0 width=1280 "), result);
        assertTrue(result.contains("scrollWidth=1280 over=0"), result);
        assertTrue(!html.contains("secret message") && !html.contains("File12.java"), "no hidden message, no ignored list");
        // What to fix first: the three failing visible items in handout order (test, data case,
        // scene), each linking to its section, on the first screen and above every image.
        assertTrue(result.contains(" fix=3 dangling=0 "), result);
        int fixTop = Integer.parseInt(result.replaceAll(".* fixTop=(-?\\d+) .*", "$1"));
        assertTrue(fixTop >= 0 && fixTop < 300, "the list is at the top of the page: " + result);
        assertTrue(result.contains("fixBeforeImages=true"), result);
        String fix = result.substring(result.indexOf("fixText="));
        int test = fix.indexOf("specular term at n.h = 1 is ks * I — wrong colour");
        int dataCase = fix.indexOf("data case: a wrong case — expected a hit at t = 2");
        int scene = fix.indexOf("scenes/showcase.json — the image differs");
        assertTrue(test >= 0 && test < dataCase && dataCase < scene, "one line per item, in handout order: " + fix);
        assertTrue(!fix.contains("hidden one") && !fix.contains("sphere.json"), "only failing visible items: " + fix);
        // The matching scene is folded; the note is shown and costs nothing.
        assertTrue(html.contains("<details style=\"margin:8px 0\"><summary>1 matching scene"), html);
        assertTrue(html.contains("your loop traced 2 shadow rays the plan could skip") && html.contains("(no points taken)"));
        // Visible points only, hidden ones named, no total: 2.5 of 6.25 visible points (the hidden 0.5 not counted).
        assertTrue(html.contains("Visible results 2.5 / 6.25") && html.contains(HtmlReport.HIDDEN_AFTER_DUE), html);
        assertTrue(!html.contains("Score "), "no total that includes hidden points");
    }

    @Test
    void instructorsReportLoadsDecodesAndFitsIn1280Pixels() throws Exception {
        String html = HtmlReport.forInstructors(sample());
        String result = probe(html, "report.html");
        System.out.println("report.html: " + result);
        assertTrue(result.startsWith("images=8 broken=0 width=1280 "), result);
        assertTrue(result.contains("scrollWidth=1280 over=0"), result);
        assertEquals(8, HtmlReport.dataUris(html).size());
    }

    @Test
    void theProbeSeesABrokenImageAndAnOverflow() throws Exception {
        // The control: a page that is wrong in both ways is reported as such.
        String result = probe("<img src=\"data:image/png;base64,AAAA\" alt=\"broken\">"
                + "<div style=\"width:2000px\">wide</div>", "bad.html");
        assertTrue(result.startsWith("images=1 broken=1 width=1280 "), result);
        assertTrue(!result.contains("over=0"), result);
    }
}
