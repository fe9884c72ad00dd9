package raylab.hidden;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import raylab.cli.Main;

/**
 * Renders several scenes in one child JVM for the grader (saves a JVM start per scene):
 * arguments are pairs SCENE.json OUT.png; for each scene the error line, if any, goes to OUT.png.err.
 */
public final class RenderMany {
    private RenderMany() {
    }

    public static void main(String[] args) throws Exception {
        for (int i = 0; i + 1 < args.length; i += 2) {
            StringWriter err = new StringWriter();
            int status;
            try {
                status = Main.run(new PrintWriter(new StringWriter()), new PrintWriter(err, true), "render", args[i], "-o",
                        args[i + 1], "--quiet", "--threads", "2");
            } catch (Throwable t) {
                status = 1;
                err.write("raylab: " + t);
            }
            if (status != 0) {
                String text = err.toString().strip();
                String last = text.isEmpty() ? "exit status " + status : text.substring(text.lastIndexOf('\n') + 1);
                Files.writeString(Path.of(args[i + 1] + ".err"), last.length() > 2000 ? last.substring(0, 2000) : last,
                        StandardCharsets.UTF_8);
                Files.deleteIfExists(Path.of(args[i + 1]));
            }
        }
        Runtime.getRuntime().halt(0);
    }
}
