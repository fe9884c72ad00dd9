package raylab.cli;

import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import raylab.course.JavaBuild;

/** Runs {@code raylab} in a JVM of its own (for heap limits, locales and signals). */
final class ChildJvm {
    private ChildJvm() {
    }

    /** A started {@code java ... raylab.cli.Main args} with the given JVM options and environment. */
    static Process start(List<String> jvmOptions, Map<String, String> env, Path stdout, Path stderr, String... args)
            throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(jvmOptions);
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add("raylab.cli.Main");
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(new File(".").getAbsoluteFile());
        pb.environment().remove("RAYLAB_DEBUG");
        pb.environment().putAll(env);
        pb.redirectOutput(stdout.toFile()).redirectError(stderr.toFile());
        return pb.start();
    }
}
