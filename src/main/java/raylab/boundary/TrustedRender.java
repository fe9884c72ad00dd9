package raylab.boundary;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.PngFiles;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Shader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * Renders scenes in the grader's process (with stand-ins whose graded methods run in the student
 * process): arguments are triples SCENE.json OUT.png NAME; for each scene the error line, if
 * any, goes to OUT.png.err. Pixel by pixel as the renderer does, so a student exception names
 * its pixel; the PNG is encoded here, never in the student's process.
 */
public final class TrustedRender {
    private TrustedRender() {
    }

    /** Renders one scene: the same pixels as {@link Renderer#render}. */
    public static Image render(Scene scene, String name) {
        Renderer r = new Renderer(scene, new RenderPlan(scene), Mode.FULL);
        Shader shader = new Shader(scene, r.root(), r.plan(), Mode.FULL);
        Image image = new Image(scene.width, scene.height);
        IntersectionRecord rec = new IntersectionRecord();
        RenderStats stats = new RenderStats();
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                Color c;
                try {
                    c = r.pixel(x, y, shader, rec, stats);
                } catch (StudentException e) {
                    throw e.in("while tracing pixel (" + x + ", " + y + ") of " + name);
                }
                image.set(x, y, c);
            }
        }
        return image;
    }

    public static void main(String[] args) throws Exception {
        for (int i = 0; i + 2 < args.length; i += 3) {
            Path out = Path.of(args[i + 1]);
            String err = null;
            try {
                Scene scene = SceneLoader.load(Path.of(args[i]));
                PngFiles.write(render(scene, args[i + 2]).toBufferedImage(), out);
            } catch (StudentException | StudentTimeout e) {
                err = e.getMessage();
            } catch (Throwable t) {
                err = t.toString();
            }
            if (err != null) {
                Files.deleteIfExists(out);
                Files.writeString(Path.of(out + ".err"), err.length() > 2000 ? err.substring(0, 2000) : err,
                        StandardCharsets.UTF_8);
            }
        }
        Runtime.getRuntime().halt(0);
    }
}
