package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import picocli.CommandLine;

/**
 * The instructor's commands are service providers ({@link OptionalCommand}, issue 38): this tree
 * lists them after the built-in ones in the services file's order; a class loader that finds no
 * services file (the starter, whose release lists none) adds none, and a listed class the build
 * lacks is simply missing.
 */
class OptionalCommandsTest {
    private static final List<String> BUILT_IN = List.of("render", "trace", "inspect", "check", "submit-check", "bench",
            "help");
    private static final List<String> INSTRUCTOR = List.of("release", "assignment", "grade", "reference", "variant",
            "bundle", "self-check", "grade-all", "study");

    @Test
    void theInstructorTreeListsItsCommandsAfterTheBuiltInOnes() {
        List<String> all = new ArrayList<>(BUILT_IN);
        all.addAll(INSTRUCTOR);
        assertEquals(all, List.copyOf(Main.commandLine().getSubcommands().keySet()));
    }

    @Test
    void withoutAServicesFileThereAreNone() throws IOException {
        CommandLine cl = new CommandLine(new Main());
        try (URLClassLoader none = new URLClassLoader(new URL[0], ClassLoader.getPlatformClassLoader())) {
            OptionalCommands.addAll(cl, none);
        }
        assertEquals(BUILT_IN, List.copyOf(cl.getSubcommands().keySet()));
    }

    @Test
    void aListedClassTheBuildLacksIsSimplyMissing(@TempDir Path dir) throws IOException {
        Path services = Files.createDirectories(dir.resolve("META-INF/services"));
        Files.writeString(services.resolve(OptionalCommand.class.getName()),
                "raylab.grade.NoSuchCommand\n" + String.class.getName() + "\n");
        CommandLine cl = new CommandLine(new Main());
        try (URLClassLoader extra = new URLClassLoader(new URL[] {dir.toUri().toURL()},
                OptionalCommand.class.getClassLoader())) {
            OptionalCommands.addAll(cl, extra);
        }
        List<String> all = new ArrayList<>(BUILT_IN);
        all.addAll(INSTRUCTOR);
        assertEquals(all, List.copyOf(cl.getSubcommands().keySet()),
                "a missing class and one that is no command are left out, the others stay");
    }
}
