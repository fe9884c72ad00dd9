package raylab.grade;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.cli.OptionalCommand;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.render.PngFiles;

/**
 * {@code raylab variant SCENE --seed N}: the variant of a graded scene that a grading with seed N
 * scores (instructors): its JSON, or with {@code -o} its reference image.
 */
@Command(name = "variant", mixinStandardHelpOptions = true,
        description = {"Show the variant of a graded scene that a grading with --seed N scores (instructors):",
            "prints its JSON, or renders its reference with the reference solution into -o OUT.png.",
            "The seed of a grading is in its report; details: docs/assignment-format.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:shown", "1:the image could not be written", "2:bad input (scene, spec or option)"})
public final class VariantCommand implements Callable<Integer>, OptionalCommand {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "A graded scene, as assignment.json lists it (scenes/NAME.json).")
    Path scene;

    @Option(names = "--seed", required = true, paramLabel = "N", description = "The grading's seed.")
    long seed;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png", description = "Render the variant's reference image here.")
    Path output;

    @Option(names = "--json", description = "Print the variant's JSON (the default without -o).")
    boolean json;

    @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project root (default: current directory).")
    Path root = Path.of(".");

    @Override
    public Integer call() throws IOException {
        Path r = root.toAbsolutePath().normalize();
        Assignments all;
        try {
            all = Assignments.load(r);
            GradedScenes.validate(r, all.all());
        } catch (IOException e) {
            throw UserError.badInput(e.getMessage());
        }
        Path wanted = scene.isAbsolute() ? scene.normalize() : Path.of("").toAbsolutePath().resolve(scene).normalize();
        for (Assignment a : all.all()) {
            for (int i = 0; i < a.scenes().size(); i++) {
                Path listed = r.resolve(a.scenes().get(i).scene()).normalize();
                if (listed.equals(wanted) || r.resolve(scene).normalize().equals(listed)) {
                    return show(r, a, i);
                }
            }
        }
        throw UserError.badInput(scene + ": not a graded scene (graded scenes are listed in assignments/*/assignment.json)");
    }

    private int show(Path r, Assignment a, int i) throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (output != null) {
            try {
                PngFiles.checkTarget(output, false);
            } catch (PngFiles.OutputException e) {
                throw UserError.badInput(e.getMessage());
            }
        }
        GradedScenes.Graded g;
        try {
            g = GradedScenes.forGrading(r, a, i, seed, output != null);
        } catch (IOException e) {
            throw UserError.badInput(e.getMessage());
        }
        err.println(a.scenes().get(i).scene() + " (milestone " + a.id() + "), grading seed " + seed + ": "
                + (g.varied() ? "variant seed " + g.seed() + (g.attempt() > 0 ? ", draw " + (g.attempt() + 1) : "")
                        + ", keeps the published scene's point" : "graded as published" + (g.note().isEmpty() ? " (no variant spec)" : ": " + g.note())));
        if (json || output == null) {
            out.print(g.json().endsWith("\n") ? g.json() : g.json() + "\n");
            out.flush();
        }
        if (output != null) {
            byte[] png = g.varied() ? g.reference() : Files.readAllBytes(r.resolve(a.scenes().get(i).reference()));
            Path tmp = Files.createTempFile(output.toAbsolutePath().getParent(), "." + output.getFileName(), ".tmp");
            try {
                Files.write(tmp, png);
                Files.move(tmp, output, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                        java.nio.file.StandardCopyOption.ATOMIC_MOVE);
            } finally {
                Files.deleteIfExists(tmp);
            }
            err.println("reference of the variant: " + output);
        }
        return 0;
    }
}
