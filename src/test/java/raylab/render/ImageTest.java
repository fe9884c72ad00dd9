package raylab.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.math.Color;

/** Image encoding to 8-bit sRGB, and PNG files: round trip and atomic writes. */
class ImageTest {
    @TempDir
    Path dir;

    @Test
    void srgbKnownValues() {
        assertEquals(0, Image.encode(0), "0 -> 0");
        assertEquals(255, Image.encode(1), "1 -> 255");
        // 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536, * 255 = 187.5 -> 188
        assertEquals(188, Image.encode(0.5), "0.5 linear -> 188");
        // linear segment below 0.0031308: 12.92 * 0.001 * 255 = 3.29 -> 3
        assertEquals(3, Image.encode(0.001), "0.001 -> 3 (linear segment)");
        // at the boundary both pieces give 0.04045, * 255 = 10.3 -> 10
        assertEquals(10, Image.encode(0.0031308), "0.0031308 -> 10");
        assertEquals(10, Image.encode(Math.nextDown(0.0031308)), "just below the boundary");
        assertEquals(10, Image.encode(Math.nextUp(0.0031308)), "just above the boundary");
        assertEquals(0, Image.encode(-0.5), "negative clamps to 0");
        assertEquals(0, Image.encode(-1e300), "very negative clamps to 0");
        assertEquals(255, Image.encode(1.0001), "above 1 clamps to 255");
        assertEquals(255, Image.encode(7), "7 clamps to 255");
    }

    /** The inverse curve (decoding), an independent formula: decode(k) must encode back to k. */
    @Test
    void encodeInvertsTheSrgbDecodingCurve() {
        for (int k = 0; k <= 255; k++) {
            double s = k / 255.0;
            double linear = s <= 0.04045 ? s / 12.92 : Math.pow((s + 0.055) / 1.055, 2.4);
            assertEquals(k, Image.encode(linear), "code " + k + " decodes to linear " + linear);
        }
    }

    @Test
    void packingAndNonFiniteColours() {
        assertEquals(0xFF0000, Image.toRgb8(new Color(1, 0, 0)), "red");
        assertEquals(0x00FF00, Image.toRgb8(new Color(0, 1, 0)), "green");
        assertEquals(0x0000FF, Image.toRgb8(new Color(0, 0, 1)), "blue");
        assertEquals((188 << 16) | (255 << 8), Image.toRgb8(new Color(0.5, 3, -2)), "mixed with clamping");
        assertEquals(0xFF00FF, Image.toRgb8(new Color(Double.NaN, 0, 0)), "NaN red -> magenta");
        assertEquals(0xFF00FF, Image.toRgb8(new Color(0, 0, Double.NaN)), "NaN blue -> magenta");
        assertEquals(0xFF00FF, Image.toRgb8(new Color(0, Double.POSITIVE_INFINITY, 0)), "+inf -> magenta");
        assertEquals(0xFF00FF, Image.toRgb8(new Color(Double.NEGATIVE_INFINITY, 0, 0)), "-inf -> magenta");
    }

    static Image gradient(int w, int h) {
        Image img = new Image(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.set(x, y, new Color((double) x / (w - 1), (double) y / (h - 1), (x + y) % 3 / 2.0));
            }
        }
        return img;
    }

    @Test
    void imageLayoutIsRowByRowFromTheTopLeft() {
        Image img = new Image(3, 2);
        img.set(2, 0, new Color(1, 0, 0));
        img.set(0, 1, new Color(0, 0, 1));
        assertEquals(new Color(1, 0, 0), img.get(2, 0), "set/get (2, 0)");
        assertEquals(new Color(0, 0, 1), img.get(0, 1), "set/get (0, 1)");
        assertEquals(Color.BLACK, img.get(1, 1), "untouched pixel is black");
        BufferedImage b = img.toBufferedImage();
        assertEquals(3, b.getWidth(), "width");
        assertEquals(2, b.getHeight(), "height");
        assertEquals(0xFF0000, b.getRGB(2, 0) & 0xFFFFFF, "red top right");
        assertEquals(0x0000FF, b.getRGB(0, 1) & 0xFFFFFF, "blue bottom left");
    }

    @Test
    void pngRoundTrip() throws IOException {
        BufferedImage written = gradient(37, 21).toBufferedImage();
        Path file = dir.resolve("sub/dir/out.png");
        PngFiles.write(written, file);
        BufferedImage read = PngFiles.read(file);
        assertEquals(37, read.getWidth(), "width");
        assertEquals(21, read.getHeight(), "height");
        for (int y = 0; y < 21; y++) {
            for (int x = 0; x < 37; x++) {
                assertEquals(written.getRGB(x, y) & 0xFFFFFF, read.getRGB(x, y) & 0xFFFFFF,
                        "pixel (" + x + ", " + y + ") after write and read");
            }
        }
        assertEquals(List.of("out.png"), names(file.getParent()), "no temporary file left");
        // overwrite an existing file
        BufferedImage other = gradient(5, 4).toBufferedImage();
        PngFiles.write(other, file);
        assertEquals(5, PngFiles.read(file).getWidth(), "the file was replaced");
        assertEquals(List.of("out.png"), names(file.getParent()), "no temporary file left after replacing");
    }

    static List<String> names(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void failedWriteToADirectoryLeavesNoTrace() throws IOException {
        Path target = dir.resolve("taken");
        Files.createDirectory(target);
        Files.writeString(target.resolve("keep.txt"), "keep");
        Path beside = dir.resolve("old.png");
        Files.writeString(beside, "old");
        assertThrows(IOException.class, () -> PngFiles.write(gradient(4, 4).toBufferedImage(), target),
                "a directory cannot be replaced by a picture");
        assertTrue(Files.isDirectory(target), "the directory is still there");
        assertEquals("keep", Files.readString(target.resolve("keep.txt")), "its content untouched");
        assertEquals(List.of("old.png", "taken"), names(dir), "no temporary file left in " + dir);
    }

    @Test
    void emptyDirectoryTargetIsNotReplacedEither() throws IOException {
        Path target = dir.resolve("empty");
        Files.createDirectory(target);
        assertThrows(IOException.class, () -> PngFiles.write(gradient(4, 4).toBufferedImage(), target),
                "an empty directory must not be replaced by a picture");
        assertTrue(Files.isDirectory(target), "the directory is still there");
        assertEquals(List.of("empty"), names(dir), "no temporary file left in " + dir);
    }

    /** A picture whose pixels cannot be read: the PNG writer fails half-way. */
    static final class BrokenImage extends BufferedImage {
        BrokenImage() {
            super(16, 16, BufferedImage.TYPE_INT_RGB);
        }

        @Override
        public Raster getData(Rectangle rect) {
            throw new IllegalStateException("broken pixels");
        }

        @Override
        public Raster getData() {
            throw new IllegalStateException("broken pixels");
        }

        @Override
        public Raster getTile(int x, int y) {
            throw new IllegalStateException("broken pixels");
        }

        @Override
        public WritableRaster getRaster() {
            throw new IllegalStateException("broken pixels");
        }

        @Override
        public WritableRaster copyData(WritableRaster r) {
            throw new IllegalStateException("broken pixels");
        }
    }

    @Test
    void failingWriterLeavesTheOldFileUnchanged() throws IOException {
        Path file = dir.resolve("picture.png");
        PngFiles.write(gradient(6, 6).toBufferedImage(), file);
        byte[] before = Files.readAllBytes(file);
        assertThrows(RuntimeException.class, () -> PngFiles.write(new BrokenImage(), file),
                "the writer fails");
        assertArrayEquals(before, Files.readAllBytes(file), "the old file is unchanged");
        assertEquals(List.of("picture.png"), names(dir), "no temporary file left in " + dir);
    }

    @Test
    void readingBadFilesFailsWithAClearMessage() throws IOException {
        IOException missing = assertThrows(IOException.class, () -> PngFiles.read(dir.resolve("none.png")));
        assertTrue(missing.getMessage().contains("none.png") && missing.getMessage().contains("no such file"),
                "message names the file: " + missing.getMessage());
        Path text = dir.resolve("text.png");
        Files.writeString(text, "not a picture");
        IOException bad = assertThrows(IOException.class, () -> PngFiles.read(text));
        assertTrue(bad.getMessage().contains("text.png"), "message names the file: " + bad.getMessage());
    }

    @Test
    void writtenPictureGetsTheUsualFilePermissions() throws IOException {
        assumeTrue(dir.getFileSystem().supportedFileAttributeViews().contains("posix"), "POSIX file system");
        Path png = dir.resolve("shared.png");
        PngFiles.write(gradient(4, 4).toBufferedImage(), png);
        Path plain = dir.resolve("plain.txt");
        Files.writeString(plain, "x");
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(png),
                "the picture must have the permissions of any new file (umask), not a temp file's owner-only ones");
    }
}
