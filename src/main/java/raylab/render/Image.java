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

    public Image(int width, int height) {
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
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
