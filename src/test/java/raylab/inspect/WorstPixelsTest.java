package raylab.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import raylab.math.Color;
import raylab.render.Image;
import raylab.render.ImageCompare;

/**
 * {@link WorstPixels#anyDiffers}, which decides whether the grader starts a student process for a
 * scene's feedback, against the images' PNG colours: seeded random pairs whose pixels differ by
 * nothing, by an 8-bit step or two, by more, in one channel, or by a value that is not finite.
 * The expected answer is read from {@link Image#toBufferedImage} (the colours the grader writes
 * to the PNGs), not from the code under test; when nothing differs, {@link WorstPixels#find}
 * traces nothing.
 */
class WorstPixelsTest {
    @TestFactory
    Stream<DynamicTest> anyDiffersIsWhetherAPngPixelDiffersByMoreThanTheThreshold() {
        return LongStream.rangeClosed(1, 40).mapToObj(seed -> DynamicTest.dynamicTest("seed " + seed, () -> {
            Random r = new Random(seed);
            Image a = new Image(9, 7);
            for (int y = 0; y < a.height; y++) {
                for (int x = 0; x < a.width; x++) {
                    a.set(x, y, new Color(r.nextDouble() * 1.2 - 0.1, r.nextDouble(), r.nextDouble()));
                }
            }
            Image b = new Image(a.width, a.height);
            for (int y = 0; y < a.height; y++) {
                for (int x = 0; x < a.width; x++) {
                    b.set(x, y, a.get(x, y));
                }
            }
            // A few pixels changed: by nothing, by under a step, by one to four 8-bit steps, or to NaN.
            for (int k = r.nextInt(4); k > 0; k--) {
                int x = r.nextInt(a.width);
                int y = r.nextInt(a.height);
                Color c = a.get(x, y);
                double d = switch (r.nextInt(4)) {
                    case 0 -> 0.0;
                    case 1 -> 1e-6;
                    case 2 -> (1 + r.nextInt(4)) / 255.0;
                    default -> Double.NaN;
                };
                b.set(x, y, new Color(c.r, c.g + d, c.b));
            }
            boolean expected = pngDiffers(a.toBufferedImage(), b.toBufferedImage());
            assertEquals(expected, WorstPixels.anyDiffers(a, b), "seed " + seed);
            assertEquals(expected, WorstPixels.anyDiffers(b, a), "seed " + seed + ", the other way round");
            if (!expected) {
                assertTrue(WorstPixels.find(a, b, (x, y) -> {
                    throw new AssertionError("seed " + seed + ": pixel (" + x + ", " + y + ") traced");
                }, null).isEmpty(), "seed " + seed);
            }
        }));
    }

    private static boolean pngDiffers(BufferedImage a, BufferedImage b) {
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                for (int shift = 0; shift <= 16; shift += 8) {
                    int p = (a.getRGB(x, y) >> shift) & 0xFF;
                    int q = (b.getRGB(x, y) >> shift) & 0xFF;
                    if (Math.abs(p - q) > ImageCompare.PIXEL_THRESHOLD) {
                        return true;
                    }
                }
            }
        }
        return false;
    }
}
