package raylab.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import raylab.camera.Camera;
import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.Color;
import raylab.surface.Surface;

/**
 * Everything to render: what is in the world (surfaces, lights, ambient light Ia, background)
 * and how to look at it (camera, image size, samples per pixel). Immutable once built.
 */
public final class Scene {
    public final Path source;
    public final int width;
    public final int height;
    public final int samplesPerPixel;
    public final Sampler sampler;
    public final Camera camera;
    public final Color background;
    /** The ambient light intensity Ia. */
    public final Color ambient;
    public final List<Surface> surfaces;
    public final List<PointLight> lights;
    public final Effects effects;

    private Scene(Builder b) {
        this.source = b.source;
        this.width = b.width;
        this.height = b.height;
        this.samplesPerPixel = b.samplesPerPixel;
        this.sampler = b.sampler;
        this.camera = b.camera;
        this.background = b.background;
        this.ambient = b.ambient;
        this.surfaces = List.copyOf(b.surfaces);
        this.lights = List.copyOf(b.lights);
        this.effects = b.effects;
    }

    /** The distinct materials of all surfaces, in order of first use. */
    public Set<Material> materials() {
        Set<Material> out = new LinkedHashSet<>();
        for (Surface s : surfaces) {
            collect(s, out);
        }
        return out;
    }

    private static void collect(Surface s, Set<Material> out) {
        if (s.material() != null) {
            out.add(s.material());
        }
        if (s instanceof raylab.surface.Group g) {
            for (Surface m : g.members()) {
                collect(m, out);
            }
        }
    }

    /** Total number of primitive shapes (a mesh counts its triangles). */
    public int primitiveCount() {
        int n = 0;
        for (Surface s : surfaces) {
            n += s.primitiveCount();
        }
        return n;
    }

    /** A copy with another number of samples per pixel. */
    public Scene withSamplesPerPixel(int spp) {
        return toBuilder().samplesPerPixel(spp).build();
    }

    /** A copy with another sampler. */
    public Scene withSampler(Sampler s) {
        return toBuilder().sampler(s).build();
    }

    /** A copy with other effect switches. */
    public Scene withEffects(Effects e) {
        return toBuilder().effects(e).build();
    }

    public Builder toBuilder() {
        Builder b = new Builder();
        b.source = source;
        b.width = width;
        b.height = height;
        b.samplesPerPixel = samplesPerPixel;
        b.sampler = sampler;
        b.camera = camera;
        b.background = background;
        b.ambient = ambient;
        b.surfaces.addAll(surfaces);
        b.lights.addAll(lights);
        b.effects = effects;
        return b;
    }

    public static Builder builder() {
        return new Builder();
    }

    /** Builds a scene; the loader and the tests use it. */
    public static final class Builder {
        private Path source;
        private int width = 64;
        private int height = 64;
        private int samplesPerPixel = 1;
        private Sampler sampler = Sampler.STRATIFIED;
        private Camera camera;
        private Color background = Color.BLACK;
        private Color ambient = Color.BLACK;
        private final List<Surface> surfaces = new ArrayList<>();
        private final List<PointLight> lights = new ArrayList<>();
        private Effects effects = Effects.AUTO;

        public Builder source(Path p) { this.source = p; return this; }
        public Builder size(int w, int h) { this.width = w; this.height = h; return this; }
        public Builder samplesPerPixel(int n) { this.samplesPerPixel = n; return this; }
        public Builder sampler(Sampler s) { this.sampler = s; return this; }
        public Builder camera(Camera c) { this.camera = c; return this; }
        public Builder background(Color c) { this.background = c; return this; }
        public Builder ambient(Color c) { this.ambient = c; return this; }
        public Builder add(Surface s) { this.surfaces.add(s); return this; }
        public Builder add(PointLight l) { this.lights.add(l); return this; }
        public Builder effects(Effects e) { this.effects = e; return this; }

        public Scene build() {
            if (camera == null) {
                throw new IllegalStateException("a scene needs a camera");
            }
            return new Scene(this);
        }
    }
}
