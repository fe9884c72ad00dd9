package raylab.render;

import java.awt.image.BufferedImage;

import raylab.math.Color;

/**
 * A picture of linear radiance values, row by row from the top-left pixel.
 *
 * <p>To 8 bits: each channel is clamped to [0, 1], encoded with the sRGB transfer curve and
 * rounded. Non-finite values (NaN, ±∞) are drawn magenta so they cannot go unnoticed.
 */
public final class Image {
    public final int width;
    public final int height;
    private final double[] rgb;

    /**
     * Heap bytes per pixel while an image is rendered and converted: 24 for the linear radiance
     * (three doubles) and 4 for the 8-bit picture, which exist together during the conversion.
     * Encoding the PNG afterwards needs less (the 8-bit picture and the compressed bytes).
     */
    public static final int BYTES_PER_PIXEL = 28;
    /** Heap kept free beside the pictures, for the renderer, the scene and the encoder. */
    static final long MARGIN = 64L << 20;

    public Image(int width, int height) {
        if (width < 1 || height < 1 || 3L * width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("image size " + width + "x" + height
                    + " out of range");
        }
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
    }

    /** Heap bytes needed to render and save a width × height image. */
    public static long bytesNeeded(int width, int height) {
        return (long) width * height * BYTES_PER_PIXEL + MARGIN;
    }

    /** Heap bytes this JVM can still allocate: its maximum heap minus what is in use now. */
    public static long availableHeap() {
        Runtime r = Runtime.getRuntime();
        return r.maxMemory() - (r.totalMemory() - r.freeMemory());
    }

    /**
     * Why a width × height image cannot be rendered with {@code available} bytes of heap, as a
     * phrase, or null when it fits. Checked before allocating so that a too-large image is one
     * clear line, never an OutOfMemoryError.
     */
    public static String memoryProblem(int width, int height, long available) {
        long need = bytesNeeded(width, height);
        if (need <= available) {
            return null;
        }
        long gib = (need + (1L << 30) - 1) >> 30;
        return String.format(java.util.Locale.ROOT, "a %dx%d image needs about %s of memory, but Java may use"
                + " only %s more; render a smaller image or give Java more memory, for example"
                + " RAYLAB_JAVA_OPTS=-Xmx%dg", width, height, size(need), size(Math.max(0, available)),
                gib + 1);
    }

    private static String size(long bytes) {
        return bytes >= (1L << 30) ? String.format(java.util.Locale.ROOT, "%.1f GiB", bytes / (double) (1L << 30))
                : String.format(java.util.Locale.ROOT, "%d MiB", bytes >> 20);
    }

    public void set(int x, int y, Color c) {
        int k = 3 * (y * width + x);
        rgb[k] = c.r;
        rgb[k + 1] = c.g;
        rgb[k + 2] = c.b;
    }

    public Color get(int x, int y) {
        int k = 3 * (y * width + x);
        return new Color(rgb[k], rgb[k + 1], rgb[k + 2]);
    }

    /** The 8-bit sRGB picture. */
    public BufferedImage toBufferedImage() {
        BufferedImage out = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                out.setRGB(x, y, toRgb8(get(x, y)));
            }
        }
        return out;
    }

    /** One colour as packed 8-bit sRGB 0xRRGGBB. */
    public static int toRgb8(Color c) {
        if (!c.isFinite()) {
            return 0xFF00FF;
        }
        return (encode(c.r) << 16) | (encode(c.g) << 8) | encode(c.b);
    }

    /** Linear value to an 8-bit sRGB code: clamp to [0, 1], sRGB curve, round. */
    public static int encode(double linear) {
        double v = Math.max(0, Math.min(1, linear));
        double s = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
        return (int) Math.round(s * 255);
    }
}
