package raylab.grade;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.cli.Main;
import raylab.cli.OptionalCommand;

/** {@code raylab reference SCENE.json}: renders a scene's reference image with the solution. */
@Command(name = "reference", mixinStandardHelpOptions = true,
        description = {"Render the reference image of a graded scene with the reference solution (instructors).",
            "Default output: reference/<name>.png next to the scene file (as listed in assignment.json)."})
public final class ReferenceCommand implements Callable<Integer>, OptionalCommand {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    Path scene;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png", description = "Where to write the image.")
    Path output;

    @Override
    public Integer call() throws Exception {
        String name = scene.getFileName().toString().replaceFirst("\\.json$", "");
        Path out = output != null ? output
                : (scene.toAbsolutePath().getParent() == null ? Path.of("reference")
                        : scene.toAbsolutePath().getParent().resolve("reference")).resolve(name + ".png");
        if (out.getParent() != null) {
            Files.createDirectories(out.getParent());
        }
        int status = Main.run(spec.commandLine().getOut(), spec.commandLine().getErr(), "render", scene.toString(),
                "-o", out.toString(), "--quiet");
        if (status == 0) {
            spec.commandLine().getOut().println("reference: " + out);
        }
        return status;
    }
}
