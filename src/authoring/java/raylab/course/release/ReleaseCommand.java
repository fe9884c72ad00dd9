package raylab.course.release;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import raylab.cli.OptionalCommand;
import raylab.cli.UserError;
import raylab.course.JavaBuild;

/**
 * {@code raylab release --out DIR}: writes the student starter and verifies it (instructor-only:
 * the starter leaves this class out, and the command line loads it by name).
 */
@Command(name = "release", mixinStandardHelpOptions = true,
        description = {"Write the student starter (solutions replaced by stubs, nothing private) and verify it.",
            "What it contains is assignments/release.json; see docs/instructors.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written and every check passed", "1:a check failed, or the starter could not be written",
            "2:bad option"})
public final class ReleaseCommand implements Callable<Integer>, OptionalCommand {
    @Spec
    CommandSpec spec;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Where to write the starter.")
    Path out;

    @Option(names = "--force", description = "Replace DIR if it is not empty.")
    boolean force;

    @Option(names = "--no-verify", description = "Write the starter without verifying it.")
    boolean noVerify;

    @Option(names = "--skip-build-check",
            description = "Verify without running the README's commands (./mvnw package, ./raylab ...) in a copy.")
    boolean skipBuildCheck;

    @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project (default: the current folder).")
    Path root = Path.of("");

    @Override
    public Integer call() throws Exception {
        PrintWriter w = spec.commandLine().getOut();
        Path project = root.toAbsolutePath().normalize();
        if (!Files.isRegularFile(project.resolve(ReleaseSpec.FILE))) {
            throw UserError.badInput(project + ": not an instructor tree (no " + ReleaseSpec.FILE + ")");
        }
        long t0 = System.nanoTime();
        Release.Written written;
        try {
            // The instructor's handouts say what the starter's say (the points of assignment.json).
            for (String h : HandoutTable.refresh(project)) {
                w.println("updated the instructor's handout " + h + " (title total and grading table from assignment.json)");
            }
            // ... and the instructor's scene schema knows the surface types registered on the class path.
            Path schema = project.resolve(Release.SCENE_SCHEMA);
            if (Files.isRegularFile(schema)) {
                String text = Files.readString(schema, java.nio.charset.StandardCharsets.UTF_8);
                String merged = raylab.scene.SurfaceTypes.schemaWithExtensions(text);
                if (!merged.equals(text)) {
                    Files.writeString(schema, merged, java.nio.charset.StandardCharsets.UTF_8);
                    w.println("updated " + Release.SCENE_SCHEMA + " with the surface types " + String.join(", ",
                            raylab.scene.SurfaceTypes.extensions().keySet()) + " (raylab.scene.SurfaceType)");
                }
            }
            written = Release.write(project, out, force);
        } catch (IOException e) {
            throw new UserError("release: " + e.getMessage(), 1);
        }
        w.printf("wrote %s: %d files, milestones %s, stubs in %d files (%.1f s)%n", written.out(), written.files(),
                String.join(", ", written.milestones()), written.stubbedFiles().size(), (System.nanoTime() - t0) / 1e9);
        w.flush();
        if (noVerify) {
            w.println("not verified (--no-verify)");
            return 0;
        }
        Path work = Files.createTempDirectory("raylab-release-verify");
        try {
            ReleaseVerifier.Report report = ReleaseVerifier.verify(project, written.out(), work,
                    new ReleaseVerifier.Options(!skipBuildCheck, 2));
            report.checks().forEach(c -> w.println(c.toString()));
            w.printf("verification %s: %d checks, %d failed (%.1f s)%n", report.passed() ? "PASSED" : "FAILED",
                    report.checks().size(), report.failures(), report.millis() / 1e3);
            w.flush();
            return report.passed() ? 0 : 1;
        } finally {
            JavaBuild.deleteTree(work);
        }
    }
}
