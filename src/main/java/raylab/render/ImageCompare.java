package raylab.render;

import java.awt.image.BufferedImage;

/**
 * Compares a rendered picture with a reference, on the 8-bit sRGB values that are in the files.
 *
 * <p>Metrics: the root-mean-square error over all channels (in units of 1/255), and the fraction
 * of pixels where some channel differs by more than a threshold. The diff image is a heatmap:
 * black where equal, through red and yellow to white at the largest difference.
 */
public final class ImageCompare {
    /** Channel difference (in 8-bit steps) above which a pixel counts as different. */
    public static final int PIXEL_THRESHOLD = 2;

    /** The outcome of a comparison. */
    public record Result(int width, int height, double rmse, double maxDifference,
            long differentPixels, BufferedImage diff) {
        /** Fraction of the pixels that differ by more than {@link #PIXEL_THRESHOLD}. */
        public double differentFraction() {
            return (double) differentPixels / ((long) width * height);
        }

        /** One line for people: "rmse 0.42/255, 0.13% pixels differ (max 7/255)". */
        public String summary() {
            return String.format("rmse %.3f/255, %d of %d pixels differ by more than %d/255 (%.3f%%), max %d/255",
                    rmse, differentPixels, (long) width * height, PIXEL_THRESHOLD,
                    100 * differentFraction(), (int) maxDifference);
        }

        /** Whether at most the given fraction of pixels differ. */
        public boolean matches(double allowedFraction) {
            return differentFraction() <= allowedFraction;
        }
    }

    private ImageCompare() {
    }

    /** Compares two pictures of the same size; throws IllegalArgumentException otherwise. */
    public static Result compare(BufferedImage actual, BufferedImage reference) {
        int w = actual.getWidth();
        int h = actual.getHeight();
        if (w != reference.getWidth() || h != reference.getHeight()) {
            throw new IllegalArgumentException("image is " + w + "x" + h + " but the reference is "
                    + reference.getWidth() + "x" + reference.getHeight());
        }
        int[] delta = new int[w * h];
        double sumSq = 0;
        int max = 0;
        long different = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int a = actual.getRGB(x, y);
                int b = reference.getRGB(x, y);
                int worst = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF));
                    sumSq += (double) d * d;
                    worst = Math.max(worst, d);
                }
                delta[y * w + x] = worst;
                max = Math.max(max, worst);
                if (worst > PIXEL_THRESHOLD) {
                    different++;
                }
            }
        }
        BufferedImage diff = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int i = 0; i < delta.length; i++) {
            diff.setRGB(i % w, i / w, heat(max == 0 ? 0 : (double) delta[i] / max));
        }
        double rmse = Math.sqrt(sumSq / (3.0 * w * h));
        return new Result(w, h, rmse, max, different, diff);
    }

    /** Black → red → yellow → white for s from 0 to 1 (also drawn as the reports' legend). */
    public static int heat(double s) {
        double r = Math.min(1, 3 * s);
        double g = Math.max(0, Math.min(1, 3 * s - 1));
        double b = Math.max(0, Math.min(1, 3 * s - 2));
        return ((int) Math.round(r * 255) << 16) | ((int) Math.round(g * 255) << 8) | (int) Math.round(b * 255);
    }
}
