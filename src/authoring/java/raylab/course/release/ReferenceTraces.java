package raylab.course.release;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.SortedMap;

import raylab.inspect.TraceFile;
import raylab.inspect.Tracer;
import raylab.render.Image;
import raylab.render.PngFiles;
import raylab.scene.Scene;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;

/**
 * The reference ray traces of the published scenes ({@code scenes/traces/NAME.trace}, read by
 * {@code raylab inspect} and {@code check}): made at release time by the reference solution (the
 * instructor tree's own classes), for every scene {@code scenes/NAME.json} of the starter that has a
 * reference image {@code scenes/reference/NAME.png}; and checked against those images by the
 * release verification. Traces are cached under {@code target/release-traces/}, keyed by the
 * scene's and the image's bytes, since the large scenes take tens of seconds.
 */
final class ReferenceTraces {
    /** The largest 8-bit difference allowed between a trace's colour and the reference image (the
     * trace keeps colours in steps of 1/4096, which can move a value by one step). */
    static final int TOLERANCE = 1;

    private ReferenceTraces() {
    }

    /** Adds the traces of the published scenes of {@code files} (the starter being built). */
    static void add(Path root, SortedMap<String, byte[]> files) throws IOException {
        for (String scene : published(files.keySet())) {
            Path json = root.resolve(scene);
            byte[] png = files.get(referenceOf(scene));
            String key = hash(files.get(scene), png);
            Path cached = root.resolve("target/release-traces")
                    .resolve(name(scene) + "-" + key + "-v" + TraceFile.FORMAT + "-" + TraceFile.MAX_TRACED + ".trace");
            if (!Files.isRegularFile(cached)) {
                Scene s;
                try {
                    s = SceneLoader.load(json);
                } catch (SceneException e) {
                    throw new IOException(scene + ": " + e.getMessage(), e);
                }
                // Written under a name of this process's own, then moved into place: two builds (two
                // test JVMs, say) that make the same trace at once never write one file together.
                Path mine = cached.resolveSibling(cached.getFileName() + "." + ProcessHandle.current().pid() + "-"
                        + java.util.UUID.randomUUID());
                TraceFile.write(new Tracer(s), mine, TraceFile.strideFor(s.width, s.height));
                Files.move(mine, cached, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            }
            files.put(traceOf(scene), Files.readAllBytes(cached));
        }
    }

    /** scenes/NAME.json of the starter with a scenes/reference/NAME.png. */
    static List<String> published(java.util.Collection<String> paths) {
        List<String> out = new ArrayList<>();
        for (String p : paths) {
            if (p.matches("scenes/[^/]+\\.json") && !p.endsWith(".schema.json") && paths.contains(referenceOf(p))) {
                out.add(p);
            }
        }
        return out;
    }

    static String name(String scene) {
        return scene.substring("scenes/".length(), scene.length() - ".json".length());
    }

    static String referenceOf(String scene) {
        return "scenes/reference/" + name(scene) + ".png";
    }

    static String traceOf(String scene) {
        return "scenes/traces/" + name(scene) + ".trace";
    }

    /**
     * The verification: every published scene of the starter has its trace, and the colour each
     * trace gives every pixel is the reference image's within {@link #TOLERANCE} steps.
     */
    static List<String> problems(Path starter, List<String> starterFiles) {
        List<String> problems = new ArrayList<>();
        for (String scene : published(starterFiles)) {
            Path trace = starter.resolve(traceOf(scene));
            if (!Files.isRegularFile(trace)) {
                problems.add(traceOf(scene) + " missing");
                continue;
            }
            try {
                Scene s = SceneLoader.load(starter.resolve(scene));
                TraceFile t = TraceFile.read(trace, s);
                BufferedImage ref = PngFiles.read(starter.resolve(referenceOf(scene)));
                long off = 0;
                int worst = 0;
                for (int y = 0; y < s.height; y += t.stride) {
                    for (int x = 0; x < s.width; x += t.stride) {
                        int a = Image.toRgb8(t.colourAt(x, y));
                        int b = ref.getRGB(x, y);
                        int d = 0;
                        for (int shift = 0; shift <= 16; shift += 8) {
                            d = Math.max(d, Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)));
                        }
                        worst = Math.max(worst, d);
                        off += d > TOLERANCE ? 1 : 0;
                    }
                }
                if (off > 0) {
                    problems.add(traceOf(scene) + ": " + off + " pixels differ from " + referenceOf(scene)
                            + " by more than " + TOLERANCE + " (max " + worst + "): trace or image out of date");
                }
            } catch (IOException | SceneException | RuntimeException e) {
                problems.add(traceOf(scene) + ": " + ReleaseVerifier.firstLine(String.valueOf(e.getMessage())));
            }
        }
        return problems;
    }

    private static String hash(byte[] scene, byte[] png) {
        try {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            d.update(scene);
            d.update(png == null ? new byte[0] : png);
            return HexFormat.of().formatHex(d.digest()).substring(0, 16);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
