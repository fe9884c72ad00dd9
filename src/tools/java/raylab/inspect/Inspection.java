package raylab.inspect;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import raylab.render.Image;
import raylab.render.PngFiles;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * The student's image and ray trees of a published scene beside the reference's: where the
 * images differ most, and the first quantity that differs there.
 */
public final class Inspection {
    /** How many of the worst pixels are traced, at most, to find one whose trees differ. */
    static final int WORST_TRIED = 32;

    public final Path scenePath;
    public final Scene scene;
    public final TraceFile reference;
    public final BufferedImage referenceImage;
    private final Tracer tracer;

    /** A pixel, its difference in the image (largest channel, 8-bit steps) and its first difference. */
    public record Finding(int x, int y, int imageDifference, FirstDifference.Difference difference) {
        /** "pixel (x, y): eye ray: your closest hit is ..." */
        public String line() {
            return "pixel (" + x + ", " + y + "): " + difference.line();
        }
    }

    private Inspection(Path scenePath, Scene scene, TraceFile reference, BufferedImage referenceImage) {
        this.scenePath = scenePath;
        this.scene = scene;
        this.reference = reference;
        this.referenceImage = referenceImage;
        this.tracer = new Tracer(scene);
    }

    /**
     * Loads a published scene with its reference trace ({@code scenes/traces/NAME.trace}) and image
     * ({@code scenes/reference/NAME.png}); an IOException with a one-line reason when either is missing.
     */
    public static Inspection of(Path scenePath) throws IOException {
        Scene scene;
        try {
            scene = SceneLoader.load(scenePath);
        } catch (raylab.scene.SceneException e) {
            throw new IOException(e.getMessage(), e);
        }
        Path trace = TraceFile.pathFor(scenePath);
        if (!Files.isRegularFile(trace)) {
            throw new IOException("no reference trace for " + scenePath + " (" + trace + "): only the published"
                    + " scenes of the starter have one");
        }
        Path png = referencePng(scenePath);
        if (!Files.isRegularFile(png)) {
            throw new IOException("no reference image for " + scenePath + " (" + png + ")");
        }
        return new Inspection(scenePath, scene, TraceFile.read(trace, scene), PngFiles.read(png));
    }

    /** {@code scenes/reference/NAME.png} for {@code scenes/NAME.json}. */
    public static Path referencePng(Path scenePath) {
        String name = scenePath.getFileName().toString().replaceFirst("\\.json$", "");
        return scenePath.toAbsolutePath().getParent().resolve("reference").resolve(name + ".png");
    }

    /** The student's ray tree of pixel (x, y), traced now through the code on the class path. */
    public RayTree mine(int x, int y) {
        return tracer.trace(x, y);
    }

    /** The reference's ray tree of pixel (x, y), which must be a {@link #traced} one. */
    public RayTree reference(int x, int y) {
        return reference.tree(x, y);
    }

    /**
     * The pixel the trees of (x, y) are shown for: (x, y) itself, or, in a scene whose reference
     * trace keeps every stride-th pixel (the large ones, to keep the starter small), the nearest such.
     */
    public int[] traced(int x, int y) {
        return reference.traced(x, y);
    }

    /** The first difference at pixel (x, y), if any; (x, y) must be a {@link #traced} pixel. */
    public Optional<FirstDifference.Difference> difference(int x, int y) {
        return FirstDifference.of(mine(x, y), reference(x, y), scene);
    }

    /** The student's picture, rendered now with the code on the class path. */
    public BufferedImage render(int threads) {
        Image img = tracer.renderer().render(threads, null);
        return img.toBufferedImage();
    }

    /**
     * The worst pixel (largest channel difference between {@code mine} and the reference image) whose
     * ray trees differ: the worst pixels are traced in order of their difference, ties in reading
     * order, until one has a first difference. Empty when the images agree or no traced pixel differs.
     */
    public Optional<Finding> worst(BufferedImage mine) {
        int w = scene.width;
        int h = scene.height;
        if (mine.getWidth() != w || mine.getHeight() != h) {
            return Optional.empty();
        }
        List<long[]> order = new ArrayList<>();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int d = channelDifference(mine.getRGB(x, y), referenceImage.getRGB(x, y));
                if (d > raylab.render.ImageCompare.PIXEL_THRESHOLD) {
                    order.add(new long[] {d, y * (long) w + x});
                }
            }
        }
        order.sort((a, b) -> a[0] != b[0] ? Long.compare(b[0], a[0]) : Long.compare(a[1], b[1]));
        java.util.Set<Long> tried = new java.util.HashSet<>();
        for (int i = 0; i < order.size() && tried.size() < WORST_TRIED; i++) {
            int[] p = traced((int) (order.get(i)[1] % w), (int) (order.get(i)[1] / w));
            int x = p[0];
            int y = p[1];
            if (!tried.add(y * (long) w + x)) {
                continue;
            }
            Optional<FirstDifference.Difference> d = difference(x, y);
            if (d.isPresent()) {
                return Optional.of(new Finding(x, y, (int) order.get(i)[0], d.get()));
            }
        }
        return Optional.empty();
    }

    static int channelDifference(int a, int b) {
        int worst = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            worst = Math.max(worst, Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)));
        }
        return worst;
    }

    /**
     * For {@code check}, run in the project folder: the first difference at the worst pixel of the student's render
     * {@code minePng} of a published scene, and the command that shows it; empty when there is no
     * reference trace or nothing to name. Never throws: what goes wrong here leaves the line out.
     */
    public static Optional<String> checkLine(String scene) {
        Path root = Path.of("").toAbsolutePath();
        String name = Path.of(scene).getFileName().toString().replaceFirst("\\.json$", "");
        return checkLine(root.resolve(scene), root.resolve("out").resolve(name + ".png"), scene);
    }

    /** As {@link #checkLine(String)}, with the render {@code minePng} (check writes it as out/NAME.png). */
    public static Optional<String> checkLine(Path scenePath, Path minePng, String shownScene) {
        try {
            Inspection in = of(scenePath);
            return in.worst(PngFiles.read(minePng)).map(f -> "first difference at " + f.line()
                    + "  (see it: ./raylab inspect " + shownScene + ")");
        } catch (IOException | RuntimeException | StackOverflowError e) {
            return Optional.empty();
        }
    }
}
