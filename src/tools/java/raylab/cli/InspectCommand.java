package raylab.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.URI;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.inspect.InspectPage;
import raylab.inspect.Inspection;
import raylab.scene.Display;

/**
 * {@code raylab inspect SCENE.json}: your render beside the reference, and for any pixel your ray
 * tree beside the reference's with the first quantity that differs, on a page served on 127.0.0.1.
 */
@Command(name = "inspect", mixinStandardHelpOptions = true, separator = " ",
        description = {"See why a pixel is wrong: a page (served on 127.0.0.1 only) with your render, the reference"
                + " and their difference.",
            "Click a pixel: your ray tree (traced now through your code) beside the reference's, quantity by quantity,"
                + " the first that differs named, and the rays drawn from above and from the side.",
            "Only the published scenes of the starter can be inspected (they ship with the reference's ray trees,"
                + " scenes/traces/)."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:stopped (Ctrl-C); with --print: no difference", "1:with --print: a difference was found",
            "2:not a published scene, or a bad option", "3:a milestone is not implemented yet"})
public final class InspectCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "A published scene (scenes/NAME.json).")
    Path scenePath;

    @Option(names = "--port", paramLabel = "N", description = "The port on 127.0.0.1 (default ${DEFAULT-VALUE};"
            + " 0: any free port).")
    int port = 8457;

    @Option(names = "--threads", paramLabel = "N", description = "Render threads (default: all cores, ${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--pixel", arity = "2", paramLabel = "X Y", hideParamSyntax = true,
            description = "With --print: this pixel instead of the worst one.")
    int[] pixel;

    @Option(names = "--print", description = "Print the first difference (at the worst pixel, or at --pixel) and exit"
            + " instead of serving the page.")
    boolean print;

    @Option(names = "--watch", description = "Render and serve again after every save of one of your files; a page left"
            + " open reloads itself. Ctrl-C stops.")
    boolean watch;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        if (watch) {
            return Watch.again(spec, true);
        }
        if (threads < 1) {
            throw UserError.badInput("--threads must be at least 1, got " + threads);
        }
        if (port < 0 || port > 65535) {
            throw UserError.badInput("--port must be between 0 and 65535, got " + port);
        }
        Inspection in;
        try {
            in = Inspection.of(scenePath);
        } catch (IOException e) {
            throw UserError.badInput(Errors.oneLine(e.getMessage()));
        }
        if (pixel != null && (pixel[0] < 0 || pixel[1] < 0 || pixel[0] >= in.scene.width || pixel[1] >= in.scene.height)) {
            throw UserError.badInput("pixel (" + pixel[0] + ", " + pixel[1] + ") is outside the " + in.scene.width + "x"
                    + in.scene.height + " image of " + Display.path(scenePath));
        }
        List<String> files = StudentFault.studentFiles(Path.of("").toAbsolutePath());
        try {
            if (print) {
                return print(out, in);
            }
            java.awt.image.BufferedImage mine = in.render(threads);
            InspectPage page = new InspectPage(in, mine, Display.path(scenePath),
                    e -> StudentFault.describe(e, files, "").orElse(Errors.oneLine(String.valueOf(e))));
            URI uri;
            try {
                uri = page.start(port);
            } catch (java.net.BindException e) {
                throw new UserError("port " + port + " on 127.0.0.1 is in use: choose another with --port N (0: any)",
                        Main.FAILED);
            }
            out.println("raylab inspect " + Display.path(scenePath) + ": open " + uri + " in your browser (Ctrl-C stops)");
            out.flush();
            Thread.currentThread().join();
            return Main.OK;
        } catch (RuntimeException | StackOverflowError e) {
            if (e instanceof raylab.course.NotImplemented || !StudentFault.isStudents(e, files)) {
                throw e;
            }
            out.flush();
            throw new UserError(StudentFault.describe(e, files, "while rendering " + Display.path(scenePath)).orElseThrow(),
                    Main.FAILED);
        }
    }

    private int print(PrintWriter out, Inspection in) {
        Optional<String> line;
        if (pixel != null) {
            int[] at = in.traced(pixel[0], pixel[1]);
            line = in.difference(at[0], at[1]).map(d -> "pixel (" + at[0] + ", " + at[1] + "): " + d.line());
        } else {
            line = in.worst(in.render(threads)).map(Inspection.Finding::line);
        }
        out.println(line.map(l -> "first difference at " + l).orElse("no difference: your ray tree"
                + (pixel != null ? " of this pixel" : "s of the differing pixels") + " match the reference's"));
        return line.isPresent() ? Main.FAILED : Main.OK;
    }
}
