package raylab.grade;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.Renderer;
import raylab.scene.Scene;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;
import raylab.shading.Shadows;
import raylab.surface.Surface;

/**
 * Whether a variant keeps its published scene's point, measured with the reference solution (in
 * the trusted grader process) on the pixel centres of the image: the same surfaces are visible
 * and each covers a share of the image within a factor of its published share; every light that
 * casts shadows in the published scene still shadows a share of the visible points within that
 * factor; every surface that shows a specular highlight still shows one, and the highlighted
 * share stays within the factor.
 */
public final class VariantCheck {
    /** Shares below this (of the image, or of the visible points) are too few pixels to compare. */
    static final double MIN_SHARE = 0.002;
    /** A pixel is highlighted where the specular term alone exceeds this in some channel. */
    static final double HIGHLIGHT = 0.1;
    /** Pixel budget of the analysis: larger images are measured at a whole fraction of their size. */
    static final int MAX_PIXELS = 120_000;

    private VariantCheck() {
    }

    /**
     * What a scene shows, counted on pixel centres.
     *
     * @param pixels      pixels measured
     * @param visible     hit pixels
     * @param coverage    hit pixels per surface name
     * @param shadowed    per light (scene order; −1 where the plan traces no shadow rays toward
     *                    it) the visible pixels it lights from the front whose shadow ray is blocked
     * @param highlights  pixels with a specular highlight, per surface name (empty without specular)
     */
    public record Profile(int pixels, int visible, Map<String, Integer> coverage, int[] shadowed,
            Map<String, Integer> highlights) {
        int highlighted() {
            return highlights.values().stream().mapToInt(Integer::intValue).sum();
        }
    }

    /** Measures a scene given as JSON text, as if read from {@code file} (meshes found beside it). */
    public static Profile analyze(JsonNode json, Path file) throws SceneException {
        ObjectNode small = json.deepCopy();
        int w = json.path("image").path("width").asInt();
        int h = json.path("image").path("height").asInt();
        int k = 1;
        while ((long) (w / k) * (h / k) > MAX_PIXELS) {
            k++;
        }
        if (k > 1) {
            ((ObjectNode) small.get("image")).put("width", w / k).put("height", h / k);
        }
        Scene scene = SceneLoader.parse(small.toString(), file);
        return analyze(scene);
    }

    /** Measures a scene. */
    public static Profile analyze(Scene scene) {
        RenderPlan plan = new RenderPlan(scene);
        Renderer renderer = new Renderer(scene, plan, Mode.FULL);
        Surface root = renderer.root();
        Image specular = plan.specular ? new Renderer(scene, plan, Mode.SPECULAR).render(2, null) : null;
        Map<String, Integer> coverage = new TreeMap<>();
        Map<String, Integer> highlights = new TreeMap<>();
        int[] shadowed = new int[scene.lights.size()];
        for (int i = 0; i < shadowed.length; i++) {
            shadowed[i] = plan.shadows[i] ? 0 : -1;
        }
        IntersectionRecord rec = new IntersectionRecord();
        IntersectionRecord scratch = new IntersectionRecord();
        int visible = 0;
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                Ray ray = scene.camera.rayThroughPixelCenter(x, y);
                rec.reset();
                if (!root.intersect(rec, ray)) {
                    continue;
                }
                visible++;
                String name = rec.surface.name();
                coverage.merge(name, 1, Integer::sum);
                Vec3 n = rec.normal.dot(ray.d) > 0 ? rec.normal.negate() : rec.normal;
                for (int i = 0; i < shadowed.length; i++) {
                    PointLight light = scene.lights.get(i);
                    if (shadowed[i] >= 0 && n.dot(light.position.minus(rec.point)) > 0
                            && Shadows.isShadowed(root, rec.point, n, light, scratch)) {
                        shadowed[i]++;
                    }
                }
                if (specular != null) {
                    Color c = specular.get(x, y);
                    if (Math.max(c.r, Math.max(c.g, c.b)) > HIGHLIGHT) {
                        highlights.merge(name, 1, Integer::sum);
                    }
                }
            }
        }
        return new Profile(scene.width * scene.height, visible, coverage, shadowed, highlights);
    }

    /**
     * What a variant loses of its published scene's point, one line each (empty: it keeps it).
     *
     * @param factor the largest ratio allowed between a variant's share and the published one
     */
    public static List<String> problems(Profile published, Profile variant, double factor, List<String> lightNames) {
        List<String> out = new ArrayList<>();
        TreeSet<String> names = new TreeSet<>(published.coverage().keySet());
        names.addAll(variant.coverage().keySet());
        for (String s : names) {
            double p = share(published.coverage().getOrDefault(s, 0), published.pixels());
            double v = share(variant.coverage().getOrDefault(s, 0), variant.pixels());
            if (p > 0 && v == 0) {
                out.add("\"" + s + "\" is out of view (published: " + pct(p) + " of the image)");
            } else if (p == 0 && v > 0) {
                out.add("\"" + s + "\" comes into view (" + pct(v) + " of the image; published: hidden)");
            } else if (p >= MIN_SHARE && !within(v, p, factor)) {
                out.add("\"" + s + "\" covers " + pct(v) + " of the image, published " + pct(p)
                        + " (allowed: a factor " + factor + ")");
            }
        }
        for (int i = 0; i < published.shadowed().length; i++) {
            if (published.shadowed()[i] <= 0) {
                continue;
            }
            double p = share(published.shadowed()[i], published.visible());
            double v = variant.shadowed()[i] < 0 ? 0 : share(variant.shadowed()[i], variant.visible());
            if (p >= MIN_SHARE && !within(v, p, factor)) {
                out.add("light \"" + lightNames.get(i) + "\" shadows " + pct(v) + " of the visible points, published "
                        + pct(p) + " (allowed: a factor " + factor + ")");
            }
        }
        for (String s : published.highlights().keySet()) {
            if (variant.highlights().getOrDefault(s, 0) == 0) {
                out.add("\"" + s + "\" shows no highlight (published: " + published.highlights().get(s) + " pixels)");
            }
        }
        double p = share(published.highlighted(), published.pixels());
        double v = share(variant.highlighted(), variant.pixels());
        if (p >= MIN_SHARE && !within(v, p, factor)) {
            out.add("highlights cover " + pct(v) + " of the image, published " + pct(p) + " (allowed: a factor " + factor + ")");
        }
        return out;
    }

    private static boolean within(double v, double p, double factor) {
        return v >= p / factor && v <= p * factor;
    }

    private static double share(int n, int of) {
        return of == 0 ? 0 : (double) n / of;
    }

    private static String pct(double f) {
        return String.format(Locale.ROOT, "%.2f%%", 100 * f);
    }
}
