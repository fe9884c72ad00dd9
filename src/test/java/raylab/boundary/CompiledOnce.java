package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * Classes compiled ({@link StandIns#compile}, against the framework's classes) into a folder once
 * per test class run: the tests that need the same classes in the same folder share them
 * (docs/testing.md, S1). Asking again for a folder with other sources is a test's mistake and fails.
 */
final class CompiledOnce {
    private final Map<Path, Map<String, String>> compiled = new HashMap<>();

    /** {@code sources} compiled into {@code out}, unless they were before: {@code out}. */
    synchronized Path compile(Map<String, String> sources, Path out) throws Exception {
        Map<String, String> before = compiled.get(out);
        if (before == null) {
            StandIns.compile(sources, StudentProcessTest.classDirs(), out);
            compiled.put(out, Map.copyOf(sources));
        } else {
            assertEquals(before, sources, "the same sources for " + out);
        }
        return out;
    }
}
