package raylab.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;

import org.junit.jupiter.api.Test;

/** ImageCompare: rmse and differing-pixel counts worked out by hand, size mismatch, heatmap. */
class ImageCompareTest {
    static BufferedImage filled(int w, int h, int rgb) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.setRGB(x, y, rgb);
            }
        }
        return img;
    }

    @Test
    void identicalImages() {
        BufferedImage a = filled(4, 5, 0x336699);
        ImageCompare.Result r = ImageCompare.compare(a, filled(4, 5, 0x336699));
        assertEquals(0.0, r.rmse(), "rmse of identical images");
        assertEquals(0, r.differentPixels(), "no differing pixels");
        assertEquals(0.0, r.maxDifference(), "no difference");
        assertTrue(r.matches(0), "matches with no tolerance");
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 4; x++) {
                assertEquals(0, r.diff().getRGB(x, y) & 0xFFFFFF, "diff black at (" + x + ", " + y + ")");
            }
        }
    }

    @Test
    void oneChangedPixel() {
        BufferedImage ref = filled(4, 5, 0x336699);
        BufferedImage act = filled(4, 5, 0x336699);
        act.setRGB(2, 3, ((0x33 + 10) << 16) | (0x66 << 8) | (0x99 - 3)); // red +10, blue -3
        ImageCompare.Result r = ImageCompare.compare(act, ref);
        // 60 channel values, squared differences 100 + 9
        assertEquals(Math.sqrt(109.0 / 60.0), r.rmse(), 1e-12, "rmse = sqrt(109 / 60)");
        assertEquals(1, r.differentPixels(), "one pixel differs by more than 2");
        assertEquals(10.0, r.maxDifference(), "largest channel difference");
        assertEquals(1.0 / 20, r.differentFraction(), 1e-15, "1 of 20 pixels");
        assertTrue(r.matches(0.05) && !r.matches(0.04), "fraction 0.05 matches 5% but not 4%");
        assertEquals(0xFFFFFF, r.diff().getRGB(2, 3) & 0xFFFFFF, "the largest difference is white in the heatmap");
        assertEquals(0x000000, r.diff().getRGB(0, 0) & 0xFFFFFF, "equal pixels are black");
        assertTrue(r.summary().contains("1 of 20"), "summary counts: " + r.summary());
    }

    @Test
    void differenceAtTheThresholdDoesNotCount() {
        BufferedImage ref = filled(3, 3, 0x808080);
        BufferedImage act = filled(3, 3, 0x808080);
        act.setRGB(1, 1, 0x828080); // red +2: not more than PIXEL_THRESHOLD
        act.setRGB(0, 0, 0x808083); // blue +3: more
        ImageCompare.Result r = ImageCompare.compare(act, ref);
        assertEquals(2, ImageCompare.PIXEL_THRESHOLD, "threshold");
        assertEquals(1, r.differentPixels(), "only the +3 pixel counts");
        assertEquals(Math.sqrt((4.0 + 9.0) / 27.0), r.rmse(), 1e-12, "rmse = sqrt(13 / 27)");
        assertFalse(r.matches(0.1), "1 of 9 is more than 10%");
    }

    @Test
    void sizeMismatchNamesBothSizes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ImageCompare.compare(filled(4, 5, 0), filled(5, 4, 0)));
        assertTrue(e.getMessage().contains("4x5") && e.getMessage().contains("5x4"),
                "message names both sizes: " + e.getMessage());
    }

    @Test
    void heatmapEndpoints() {
        assertEquals(0x000000, ImageCompare.heat(0), "0 -> black");
        assertEquals(0xFF0000, ImageCompare.heat(1.0 / 3), "1/3 -> red");
        assertEquals(0xFFFF00, ImageCompare.heat(2.0 / 3), "2/3 -> yellow");
        assertEquals(0xFFFFFF, ImageCompare.heat(1), "1 -> white");
        int mid = ImageCompare.heat(0.5);
        assertEquals(0xFF, mid >> 16, "0.5: full red");
        assertEquals(128, (mid >> 8) & 0xFF, "0.5: half green");
        assertEquals(0, mid & 0xFF, "0.5: no blue");
    }
}
