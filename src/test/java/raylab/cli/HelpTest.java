package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

import picocli.CommandLine;

/** Every command's --help prints its usage and nothing on standard error (no picocli warnings). */
class HelpTest {
    /** Every command path: [], [render], [grade, ...] for the commands of this tree. */
    static List<List<String>> commands(CommandLine cl, List<String> prefix) {
        List<List<String>> out = new ArrayList<>();
        out.add(prefix);
        for (var e : cl.getSubcommands().entrySet()) {
            if (e.getValue().getCommandName().equals(e.getKey()) && !e.getKey().equals("help")) {
                List<String> p = new ArrayList<>(prefix);
                p.add(e.getKey());
                out.addAll(commands(e.getValue(), p));
            }
        }
        return out;
    }

    @TestFactory
    Stream<DynamicTest> everyHelpHasAnEmptyStandardError() {
        return commands(Main.commandLine(), List.of()).stream().map(path -> DynamicTest.dynamicTest(
                "raylab " + String.join(" ", path) + " --help", () -> {
                    List<String> args = new ArrayList<>(path);
                    args.add("--help");
                    StringWriter out = new StringWriter();
                    StringWriter err = new StringWriter();
                    ByteArrayOutputStream system = new ByteArrayOutputStream();
                    PrintStream saved = System.err;
                    int status;
                    try {
                        System.setErr(new PrintStream(system, true, StandardCharsets.UTF_8));
                        status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new));
                    } finally {
                        System.setErr(saved);
                    }
                    String stderr = err + system.toString(StandardCharsets.UTF_8);
                    assertEquals("", stderr, "standard error of raylab " + String.join(" ", args));
                    assertEquals(0, status, "exit status of raylab " + String.join(" ", args));
                    assertTrue(out.toString().startsWith("Usage: raylab"), "usage expected, got: " + out);
                }));
    }

    @Test
    void traceUsageShowsThePixelOnce() {
        StringWriter out = new StringWriter();
        Main.run(new PrintWriter(out, true), new PrintWriter(new StringWriter(), true), "trace", "--help");
        String first = out.toString().lines().findFirst().orElse("");
        assertTrue(first.contains("--pixel X Y") && !first.contains("X Y X Y") && !first.contains("--pixel="),
                "usage line: " + first);
    }

    @Test
    void theCommandsAreListed() {
        List<List<String>> all = commands(Main.commandLine(), List.of());
        for (String c : List.of("render", "trace", "check", "bench", "submit-check")) {
            assertTrue(all.contains(List.of(c)), "command " + c + " in " + all);
        }
    }
}
