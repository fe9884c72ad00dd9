package raylab.cli;

import java.util.Iterator;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;

import picocli.CommandLine;

/**
 * Adds the {@link OptionalCommand}s this build provides (the instructor's tree has them, the
 * student release none) to the command line, in the order of their services file.
 */
final class OptionalCommands {
    private OptionalCommands() {
    }

    static void addAll(CommandLine cl) {
        addAll(cl, OptionalCommand.class.getClassLoader());
    }

    /** As {@link #addAll(CommandLine)}, with the services files and providers {@code loader} finds. */
    static void addAll(CommandLine cl, ClassLoader loader) {
        Iterator<OptionalCommand> it = ServiceLoader.load(OptionalCommand.class, loader).iterator();
        while (true) {
            try {
                if (!it.hasNext()) {
                    return;
                }
                cl.addSubcommand(it.next());
            } catch (ServiceConfigurationError absent) {
                // A listed class this build lacks or cannot make: that command is simply missing.
            }
        }
    }
}
