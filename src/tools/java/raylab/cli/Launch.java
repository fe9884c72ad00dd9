package raylab.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import raylab.course.JavaBuild;

/**
 * The entry the {@code raylab} launcher script runs: brings {@code target/incremental} up to date
 * (the student files changed since the full build, compiled alone, see {@link Incremental}), then
 * runs the command line. Exit status {@link Incremental#FULL_BUILD} asks the script for a full
 * Maven build (another source or pom.xml changed); a compile error is printed as javac gives it
 * and exits with status 1.
 */
public final class Launch {
    private Launch() {
    }

    /** The project folder: -Draylab.home (the script sets it), else the working folder. */
    public static Path home() {
        return Path.of(System.getProperty("raylab.home", "")).toAbsolutePath().normalize();
    }

    public static void main(String[] args) {
        int status = prepare(home());
        if (status != Main.OK) {
            System.exit(status);
        }
        Main.main(args);
    }

    /** Compiles what changed; returns 0 to go on, 1 after a compile error, or FULL_BUILD. */
    static int prepare(Path home) {
        Incremental inc = Incremental.of(home);
        if (!Files.isRegularFile(home.resolve("target/raylab.jar"))) {
            return Main.OK; // not run from a built project (a test, the IDE): nothing to bring up to date
        }
        try {
            JavaBuild.Result r = inc.update(JavaBuild.ownClassPath());
            if (r == null) {
                return Incremental.FULL_BUILD;
            }
            if (!r.success()) {
                System.err.print(CompileErrors.text(r.errors(), home));
                System.err.println("raylab: your code does not compile (" + r.errors().size() + " error"
                        + (r.errors().size() == 1 ? "" : "s") + "): fix it and run the command again");
                return Main.FAILED;
            }
            return Main.OK;
        } catch (IOException | RuntimeException e) {
            System.err.println("raylab: the quick build failed (" + Errors.oneLine(e.getMessage())
                    + "); run ./mvnw -q -DskipTests package for the full build");
            return Main.FAILED;
        }
    }
}
