package raylab.cli;

import java.io.PrintWriter;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code raylab} command line. Exit status: 0 success, 1 failure (an image differs from its
 * reference, a file cannot be written), 2 bad input (a scene or an option), 3 a milestone that is
 * not implemented yet.
 */
@Command(name = "raylab", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "A ray tracer for learning: render scenes, trace one pixel, check milestones.",
        subcommands = {RenderCommand.class, TraceCommand.class, InspectCommand.class, CheckCommand.class, SubmitCheckCommand.class,
            BenchCommand.class,
            CommandLine.HelpCommand.class})
public final class Main implements Runnable {
    public static final int OK = 0;
    public static final int FAILED = 1;
    public static final int BAD_INPUT = 2;
    public static final int NOT_IMPLEMENTED = 3;

    private static final java.util.regex.Pattern BAD_PATH = java.util.regex.Pattern.compile(
            "cannot convert '(.*)' to interface java\\.nio\\.file\\.Path \\(java\\.nio\\.file\\."
                    + "InvalidPathException: ([^:]*)", java.util.regex.Pattern.DOTALL);

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }

    /** Whether this JVM runs one command line ({@link #main}): only then may a command end it at once. */
    static volatile boolean standalone;

    public static void main(String[] args) {
        standalone = true;
        System.exit(run(args));
    }

    /** Runs a command line and returns its exit status (never calls System.exit). */
    public static int run(String... args) {
        return run(new PrintWriter(System.out, true), new PrintWriter(System.err, true), args);
    }

    /** Runs a command line with the given output streams and returns its exit status. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        CommandLine cl = commandLine();
        cl.setOut(out);
        cl.setErr(err);
        try {
            return cl.execute(args);
        } catch (OutOfMemoryError e) {
            // The last resort: sizes are checked before allocating, but never a stack trace.
            err.println("raylab: out of memory (" + Errors.oneLine(e.getMessage()) + "); give Java more"
                    + " memory, for example RAYLAB_JAVA_OPTS=-Xmx8g");
            return FAILED;
        }
    }

    /** The configured picocli command line (also used to list the subcommands in docs). */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.setExecutionExceptionHandler(new Errors());
        cl.setParameterExceptionHandler((ex, args) -> {
            PrintWriter err = ex.getCommandLine().getErr();
            // picocli keeps only the text of a failed conversion: a file name that the locale cannot
            // encode (LANG=C) or that holds a NUL character.
            java.util.regex.Matcher bad = BAD_PATH.matcher(String.valueOf(ex.getMessage()));
            if (bad.find()) {
                err.println("raylab: " + Errors.oneLine(bad.group(1)) + ": not a usable file name ("
                        + Errors.oneLine(bad.group(2)) + "; the file-name encoding is "
                        + System.getProperty("sun.jnu.encoding") + "); use ASCII names or a UTF-8 locale"
                        + " (LANG=C.UTF-8)");
                return BAD_INPUT;
            }
            err.println("raylab: " + Errors.oneLine(ex.getMessage()) + " (see: "
                    + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help)");
            return BAD_INPUT;
        });
        OptionalCommands.addAll(cl);
        return cl;
    }

    /** The version from the jar's manifest, or "development". */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"raylab " + (v == null ? "development" : v),
                "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")"};
        }
    }
}
