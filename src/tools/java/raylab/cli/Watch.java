package raylab.cli;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;

import raylab.course.JavaBuild;

/**
 * {@code check --watch} and {@code render --watch}: runs the command, then again after every save
 * of a student file (or of the given extra files), each time on a cleared screen. A run compiles
 * the changed student files (as the launcher does, {@link Incremental}) and runs the command in a
 * JVM of its own, so that it sees the new classes. Ctrl-C stops it, and the run under way with it.
 */
final class Watch {
    /** How often the files' times are looked at. */
    static final long POLL_MILLIS = 250;
    /** Clears the terminal and puts the cursor at the top (ANSI). */
    static final String CLEAR = "\033[H\033[2J";

    private Watch() {
    }

    /** Runs the command line of {@code spec} without --watch, as {@link #run(PrintWriter, List, List, boolean)}. */
    static int again(picocli.CommandLine.Model.CommandSpec spec, boolean restart) throws IOException {
        return run(spec.commandLine().getOut(), without(spec.commandLine().getParseResult().originalArgs()
                .toArray(String[]::new)), List.of(), restart);
    }

    /** Runs the command line of {@code spec} without --watch, again after every save of a student file or {@code extra}. */
    static int again(picocli.CommandLine.Model.CommandSpec spec, List<Path> extra) throws IOException {
        return run(spec.commandLine().getOut(), without(spec.commandLine().getParseResult().originalArgs()
                .toArray(String[]::new)), extra, false);
    }

    /**
     * Runs {@code raylab ARGS} (the command line without --watch) now and after every change of
     * the student files or {@code extra}; returns only when interrupted. With {@code restart} the
     * command (a server such as {@code inspect}, which runs until stopped) is stopped and started
     * again at every save.
     */
    static int run(PrintWriter out, List<String> args, List<Path> extra, boolean restart) throws IOException {
        Path home = Launch.home();
        List<Path> files = new ArrayList<>();
        for (String f : StudentFault.studentFiles(home)) {
            files.add(home.resolve(f));
        }
        files.addAll(extra);
        Process[] running = new Process[1];
        Thread stop = new Thread(() -> {
            Process p = running[0];
            if (p != null) {
                p.descendants().forEach(ProcessHandle::destroy);
                p.destroy();
            }
            out.println();
            out.println("raylab: stopped watching");
            out.flush();
        });
        Runtime.getRuntime().addShutdownHook(stop);
        String seen = stamps(files);
        for (int n = 1;; n++) {
            out.print(CLEAR);
            out.println("raylab " + String.join(" ", args) + "  (run " + n + " at "
                    + LocalTime.now().format(DateTimeFormatter.ofPattern("HH:mm:ss")) + "; watching " + files.size()
                    + " files, Ctrl-C stops)");
            out.println();
            out.flush();
            if (compile(out, home)) {
                // Started as the raylab launcher starts a command (JavaBuild.QUICK_JVM).
                List<String> cmd = new ArrayList<>(List.of(JavaBuild.javaExecutable()));
                cmd.addAll(JavaBuild.QUICK_JVM);
                cmd.addAll(List.of("-Draylab.home=" + home, "-cp", String.join(File.pathSeparator,
                                JavaBuild.ownClassPath().stream().map(p -> p.toAbsolutePath().toString()).toList()),
                        Main.class.getName()));
                cmd.addAll(args);
                running[0] = new ProcessBuilder(cmd).inheritIO().start();
                try {
                    while (restart && running[0].isAlive() && stamps(files).equals(seen)) {
                        Thread.sleep(POLL_MILLIS);
                    }
                    if (restart && running[0].isAlive()) {
                        running[0].descendants().forEach(ProcessHandle::destroy);
                        running[0].destroy();
                    }
                    running[0].waitFor();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return Main.OK;
                }
                running[0] = null;
            }
            out.println();
            out.println("raylab: waiting for the next save ...");
            out.flush();
            try {
                String now;
                while ((now = stamps(files)).equals(seen)) {
                    Thread.sleep(POLL_MILLIS);
                }
                seen = now;
                Thread.sleep(POLL_MILLIS); // an editor may write a file in several steps
                seen = stamps(files);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return Main.OK;
            }
        }
    }

    /** Brings target/incremental up to date; false (with the errors printed) when the code does not compile. */
    private static boolean compile(PrintWriter out, Path home) {
        if (!Files.isRegularFile(home.resolve("target/raylab.jar"))) {
            return true;
        }
        try {
            JavaBuild.Result r = Incremental.of(home).update(JavaBuild.ownClassPath());
            if (r == null) {
                out.println("raylab: a framework file or pom.xml changed: stop (Ctrl-C) and run ./raylab again for"
                        + " the full build");
                return false;
            }
            if (!r.success()) {
                out.print(CompileErrors.text(r.errors(), home));
                out.println("raylab: your code does not compile (" + r.errors().size() + " error"
                        + (r.errors().size() == 1 ? "" : "s") + "): fix it and save again");
                return false;
            }
            return true;
        } catch (IOException | RuntimeException e) {
            out.println("raylab: the quick build failed: " + Errors.oneLine(e.getMessage()));
            return false;
        }
    }

    /** Size and time of every file, as one string (a missing file counts as a state too). */
    static String stamps(List<Path> files) {
        StringBuilder b = new StringBuilder();
        for (Path p : files) {
            try {
                b.append(Files.size(p)).append('@').append(Files.getLastModifiedTime(p).toMillis()).append(';');
            } catch (IOException e) {
                b.append("missing;");
            }
        }
        return b.toString();
    }

    /** The command line without --watch. */
    static List<String> without(String[] args) {
        List<String> out = new ArrayList<>();
        for (String a : args) {
            if (!a.equals("--watch")) {
                out.add(a);
            }
        }
        return out;
    }
}
