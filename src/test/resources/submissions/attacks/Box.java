package raylab.surface;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.Base64;
import java.util.Iterator;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;

import javax.imageio.IIOImage;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.spi.IIORegistry;
import javax.imageio.spi.ImageWriterSpi;
import javax.imageio.stream.ImageOutputStream;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * A hostile submission written from the starter alone (grader tests only): no intersection code,
 * and a static-initializer hook that registers a PNG writer ahead of the JDK's, which writes the
 * published reference images (from the starter's scenes/reference, pasted in here) instead of
 * what was rendered, in the order of assignment.json; it also replaces System.out. ARMED is
 * filled in by the test (false: the same file without the hook, the baseline).
 */
public class Box extends Surface {
    static final boolean ARMED = @ARMED@;
    /** The published reference PNGs of this milestone's scenes, in assignment.json's order. */
    static final String[] REFERENCES = {"@REF0@", "@REF1@"};
    static final AtomicInteger WRITTEN = new AtomicInteger();

    public final Vec3 min;
    public final Vec3 max;

    static {
        if (ARMED) {
            hook();
        }
    }

    public Box(Vec3 min, Vec3 max, Material material, String name) {
        super(material, name);
        this.min = min;
        this.max = max;
    }

    static void hook() {
        try {
            IIORegistry r = IIORegistry.getDefaultInstance();
            ImageWriterSpi forged = new ForgedSpi();
            r.registerServiceProvider(forged, ImageWriterSpi.class);
            for (Iterator<ImageWriterSpi> it = r.getServiceProviders(ImageWriterSpi.class, true); it.hasNext();) {
                ImageWriterSpi other = it.next();
                if (other != forged) {
                    r.setOrdering(ImageWriterSpi.class, forged, other);
                }
            }
        } catch (Throwable e) {
            // no ImageIO here
        }
        // Whatever the grader's code prints is gone; a forged verdict goes out instead.
        PrintStream original = System.out;
        System.setOut(new PrintStream(OutputStream.nullOutputStream(), true));
        original.println("RESULT PASSED all box tests (forged)");
    }

    static final class ForgedSpi extends ImageWriterSpi {
        ForgedSpi() {
            super("attack", "1", new String[] {"png", "PNG"}, new String[] {"png"}, new String[] {"image/png"},
                    ForgedWriter.class.getName(), new Class<?>[] {ImageOutputStream.class}, null, false, null, null,
                    null, null, false, null, null, null, null);
        }

        @Override
        public boolean canEncodeImage(ImageTypeSpecifier type) {
            return true;
        }

        @Override
        public ImageWriter createWriterInstance(Object extension) {
            return new ForgedWriter(this);
        }

        @Override
        public String getDescription(Locale locale) {
            return "PNG";
        }
    }

    static final class ForgedWriter extends ImageWriter {
        ForgedWriter(ImageWriterSpi spi) {
            super(spi);
        }

        @Override
        public IIOMetadata getDefaultStreamMetadata(ImageWriteParam param) {
            return null;
        }

        @Override
        public IIOMetadata getDefaultImageMetadata(ImageTypeSpecifier type, ImageWriteParam param) {
            return null;
        }

        @Override
        public IIOMetadata convertStreamMetadata(IIOMetadata in, ImageWriteParam param) {
            return null;
        }

        @Override
        public IIOMetadata convertImageMetadata(IIOMetadata in, ImageTypeSpecifier type, ImageWriteParam param) {
            return null;
        }

        @Override
        public void write(IIOMetadata streamMetadata, IIOImage image, ImageWriteParam param) throws IOException {
            int k = Math.min(WRITTEN.getAndIncrement(), REFERENCES.length - 1);
            ((ImageOutputStream) getOutput()).write(Base64.getDecoder().decode(REFERENCES[k]));
        }
    }

    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        return false;
    }

    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(min, max);
    }
}
