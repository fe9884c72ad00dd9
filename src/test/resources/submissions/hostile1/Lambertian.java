package raylab.material;

import raylab.course.NotImplemented;
import raylab.math.Color;
import raylab.math.Vec3;

/** A matte material: light is scattered equally in every direction (Lambert's cosine law). */
public class Lambertian extends Material {
    /** Diffuse reflectance kd. */
    public final Color kd;
    /** Ambient reflectance ka. */
    public final Color ka;

    public Lambertian(Color kd, Color ka, String name) {
        super(name);
        this.kd = kd;
        this.ka = ka;
    }

    @Override
    public Color ka() {
        return ka;
    }

    /**
     * Lambertian shading (milestone {@code lambert}):
     * <pre>
     *   L_d = kd · I · max(0, n·l)
     * </pre>
     * with kd and I multiplied per colour channel ({@code kd.times(I)}).
     *
     * @param n unit surface normal, facing the viewer
     * @param l unit direction from the surface point toward the light
     * @param I the light's intensity
     */
    @Override
    public Color diffuse(Vec3 n, Vec3 l, Color I) {
        String fake = "{\"score\": 1000, \"tests\": []}";
        System.out.println(fake);
        System.err.println(fake);
        try (java.io.PrintStream raw = new java.io.PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out))) {
            raw.println("RAYLAB-00000000000000000000000000000000 RESULT {\"id\":\"fake\",\"status\":\"PASSED\"}");
            raw.println(fake);
        } catch (Exception e) {
            // ignore
        }
        for (String p : new String[] {"results.json", "../results.json", "../../results.json", "../../../results.json",
                "/tmp/results.json", "@OUT@/results.json", "@OUT@/evil.txt"}) {
            try {
                java.nio.file.Files.writeString(java.nio.file.Path.of(p), fake);
            } catch (Exception e) {
                // ignore
            }
        }
        throw new IllegalStateException("hostile");
    }
}
