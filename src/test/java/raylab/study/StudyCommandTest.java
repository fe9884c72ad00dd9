package raylab.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.bench.MachineInfo;
import raylab.cli.Main;

/** {@code raylab study --quick} writes the whole report: every plot, the stamp, conclusions first. No timing is checked. */
class StudyCommandTest {
    /** The plots the issue asks for, one file each. */
    static final List<String> PLOTS = List.of(
            "sampling-front.png", "sampling-error.png",
            "sphere-front.png", "sphere-wrong.png", "sphere-error.png",
            "triangle-front.png", "triangle-cracks.png",
            "shadow-front.png", "shadow-acne.png", "shadow-leaks.png",
            "bvh-front.png", "bvh-time-per-ray.png", "bvh-tests-per-ray.png", "bvh-build-time.png",
            "box-front.png", "box-wrong.png",
            "plan-front.png");

    static int run(StringWriter out, StringWriter err, String... args) {
        return Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
    }

    @Test
    void quickStudyWritesTheFullReport(@TempDir Path dir) throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = run(out, err, "study", "--out", dir.toString(), "--quick");
        assertEquals(0, status, "exit status of study --quick; stderr:\n" + err);

        Path report = dir.resolve("report.md");
        assertTrue(Files.isRegularFile(report), "expected " + report + " to exist; directory holds " + list(dir));
        String md = Files.readString(report);
        for (String plot : PLOTS) {
            Path png = dir.resolve(plot);
            assertTrue(Files.isRegularFile(png), "expected plot " + png + "; directory holds " + list(dir));
            BufferedImage img = ImageIO.read(png.toFile());
            assertTrue(img != null && img.getWidth() >= 400 && img.getHeight() >= 300,
                    plot + ": expected a readable PNG at least 400x300, got " + (img == null ? "unreadable" : img.getWidth() + "x" + img.getHeight()));
            assertTrue(md.contains("](" + plot + ")"), "expected the report to embed " + plot);
        }
        String machine = MachineInfo.current().oneLine();
        assertTrue(md.contains("**Machine:** " + machine.substring(0, machine.lastIndexOf(',') + 1)),
                "expected the machine/JVM stamp '" + machine + "' in the report header:\n" + head(md));
        assertTrue(md.contains("Java") || md.contains("VM"), "expected the JVM in the stamp:\n" + head(md));

        int conclusions = md.indexOf("\n## Conclusions\n");
        int firstSection = md.indexOf("\n## ", conclusions + 1);
        assertTrue(conclusions > 0, "expected a '## Conclusions' section:\n" + head(md));
        int firstOther = md.indexOf("\n## ");
        assertEquals(conclusions, firstOther, "expected the conclusions to be the first section:\n" + head(md));
        String bullets = md.substring(conclusions, firstSection);
        long count = bullets.lines().filter(l -> l.startsWith("- **")).count();
        assertEquals(StudyCommand.experiments().size(), count,
                "expected one conclusion per experiment, got:\n" + bullets);
        // Every experiment section opens with its error-against-cost front.
        long sections = 0;
        for (String part : md.substring(firstSection).split("\n## ")) {
            String title = part.lines().findFirst().orElse("").strip();
            if (title.isEmpty() || title.startsWith("How this agrees")) {
                continue;
            }
            sections++;
            String first = part.lines().skip(1).filter(l -> !l.isBlank()).findFirst().orElse("");
            assertTrue(first.startsWith("![") && first.endsWith("-front.png)"),
                    "expected section '" + title + "' to open with its front plot, got: " + first);
        }
        assertEquals(StudyCommand.experiments().size(), sections, "expected one section per experiment");
        assertTrue(md.contains("**Machine noise:**") && md.contains("**Load average**") && md.contains("**Decision rule**"),
                "expected the noise, the load average and the decision rule in the header:\n" + head(md));
        // Measured figures live in the conclusions and the tables: none of them may be NaN or infinite.
        String figures = bullets + "\n" + String.join("\n", md.lines().filter(l -> l.startsWith("|")).toList());
        assertTrue(!figures.contains("NaN") && !figures.contains("Infinity"),
                "expected no NaN or Infinity among the figures:\n" + figures);
    }

    @Test
    void unknownExperimentIsOneLineBadInput(@TempDir Path dir) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = run(out, err, "study", "--out", dir.toString(), "--only", "nope");
        assertEquals(Main.BAD_INPUT, status, "exit status for --only nope; stderr: " + err);
        assertEquals(1, err.toString().strip().lines().count(), "expected a one-line error, got:\n" + err);
        assertTrue(err.toString().contains("nope"), "expected the message to name 'nope': " + err);
    }

    @Test
    void outIsRequired() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = run(out, err, "study", "--quick");
        assertEquals(Main.BAD_INPUT, status, "exit status without --out; stderr: " + err);
        assertTrue(err.toString().contains("--out"), "expected the message to name --out: " + err);
    }

    private static String head(String md) {
        return md.substring(0, Math.min(md.length(), 1500));
    }

    private static String list(Path dir) throws Exception {
        try (var s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList().toString();
        }
    }
}
