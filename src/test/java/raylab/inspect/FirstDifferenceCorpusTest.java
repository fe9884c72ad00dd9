package raylab.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

/**
 * The corpus of {@link InspectCorpus#BUGS} (10 planted mistakes, each in a published scene where it
 * changes the image): the first difference named at the worst pixel is the planted mistake in at
 * least 9 of 10, and never a method of a file the student wrote correctly; for the correct code
 * (the reference) no scene has anything to name.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class FirstDifferenceCorpusTest {
    @TempDir
    static Path dir;
    Path scenes;

    @BeforeAll
    void traces() throws Exception {
        scenes = InspectCorpus.scenesWithTraces(dir, InspectCorpus.BUGS.stream().map(InspectCorpus.Bug::scene)
                .distinct().toList(), true);
    }

    @Test
    void theWorstPixelNamesThePlantedMistakeInAtLeast9Of10() throws Exception {
        List<String> named = new ArrayList<>();
        List<String> report = new ArrayList<>();
        int i = 0;
        for (InspectCorpus.Bug b : InspectCorpus.BUGS) {
            Path classes = InspectCorpus.compile(b.file(), dir.resolve("bug" + i++));
            String[] w;
            try (URLClassLoader l = InspectCorpus.loader(classes)) {
                w = InspectCorpus.worst(l, scenes.resolve(b.scene() + ".json"));
            }
            String line = w == null ? "nothing named" : "pixel (" + w[0] + ", " + w[1] + "): " + w[3];
            report.add(b + " -> " + line);
            String buggyClass = Path.of(b.file()).getFileName().toString().replace(".java", "");
            if (w != null) {
                // Never blames correct code: the method named is one of the buggy file's.
                assertTrue(w[2].startsWith(buggyClass + "."), () -> b + ": expected a method of " + buggyClass
                        + " (the only file with a mistake), the first difference names " + w[2] + ": " + w[3]);
                if (w[2].equals(b.method()) && w[3].contains(b.phrase())) {
                    named.add(b.file());
                }
            }
        }
        System.out.println("first difference at the worst pixel, " + named.size() + " of " + InspectCorpus.BUGS.size()
                + " planted mistakes named:\n  " + String.join("\n  ", report));
        assertTrue(named.size() >= 9, "expected the planted mistake named in at least 9 of "
                + InspectCorpus.BUGS.size() + ", was " + named.size() + ":\n" + String.join("\n", report));
    }

    /** What check prints under a differing scene: the worst pixel's first difference and the inspect command. */
    @Test
    void checksLineNamesTheWorstPixelsFirstDifferenceAndTheInspectCommand() throws Exception {
        Path classes = InspectCorpus.compile("inspect/sphere-farther-root/Sphere.java", dir.resolve("check"));
        try (URLClassLoader l = InspectCorpus.loader(classes)) {
            Class<?> in = l.loadClass("raylab.inspect.Inspection");
            Path scene = scenes.resolve("spheres.json");
            Object inspection = in.getMethod("of", Path.class).invoke(null, scene);
            java.awt.image.BufferedImage mine = (java.awt.image.BufferedImage) in.getMethod("render", int.class)
                    .invoke(inspection, 1);
            Path png = dir.resolve("spheres.png");
            javax.imageio.ImageIO.write(mine, "png", png.toFile());
            @SuppressWarnings("unchecked")
            java.util.Optional<String> line = (java.util.Optional<String>) in.getMethod("checkLine", Path.class,
                    Path.class, String.class).invoke(null, scene, png, "scenes/spheres.json");
            String got = line.orElse("none");
            assertTrue(got.matches("first difference at pixel \\(\\d+, \\d+\\): eye ray: your closest hit is 'behind' at t = .*"
                    + "your Sphere\\.intersect returns the farther root.*  \\(see it: \\./raylab inspect scenes/spheres\\.json\\)"),
                    "expected check's line: the worst pixel's first difference naming the farther root, then the inspect"
                    + " command; was: " + got);
        }
        // The reference's own render: nothing to say.
        assertEquals(java.util.Optional.empty(), Inspection.checkLine(scenes.resolve("spheres.json"),
                scenes.resolve("reference/spheres.png"), "scenes/spheres.json"), "no line when the images agree");
    }

    @Test
    void theReferenceHasNothingToName() throws Exception {
        try (URLClassLoader l = InspectCorpus.loader(null)) {
            for (String scene : InspectCorpus.BUGS.stream().map(InspectCorpus.Bug::scene).distinct().toList()) {
                String[] w = InspectCorpus.worst(l, scenes.resolve(scene + ".json"));
                assertNull(w, () -> scene + ": expected no difference for the reference, got " + String.join(" | ", w));
            }
        }
    }

    @Test
    void theTraceFileGivesBackTheReferenceTreesWithinItsRounding() throws Exception {
        Path json = scenes.resolve("shadows.json");
        var scene = raylab.scene.SceneLoader.load(json);
        TraceFile f = TraceFile.read(TraceFile.pathFor(json), scene);
        Tracer t = new Tracer(scene);
        long seed = 40;
        java.util.SplittableRandom r = new java.util.SplittableRandom(seed);
        for (int k = 0; k < 500; k++) {
            int[] p = f.traced(r.nextInt(scene.width), r.nextInt(scene.height));
            int x = p[0];
            int y = p[1];
            RayTree live = t.trace(x, y);
            RayTree stored = f.tree(x, y);
            var d = FirstDifference.of(live, stored, scene);
            assertTrue(d.isEmpty(), () -> "seed " + seed + ", pixel (" + x + ", " + y + "): expected no difference between"
                    + " the live and the stored reference tree, got " + d.get().line());
            assertEquals(live.surface, stored.surface, "seed " + seed + ", pixel (" + x + ", " + y + ") surface");
        }
    }
}
