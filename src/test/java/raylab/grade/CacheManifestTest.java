package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The grader cache's hash manifest: every kind of change is caught, and a bad cache is not used. */
class CacheManifestTest {
    @TempDir
    Path dir;

    private Path cache() throws IOException {
        Path c = Files.createDirectories(dir.resolve("cache"));
        Files.createDirectories(c.resolve("ref/sphere/raylab/surface"));
        Files.write(c.resolve("ref/sphere/raylab/surface/Sphere.class"), new byte[] {(byte) 0xca, (byte) 0xfe, 1, 2});
        Files.writeString(c.resolve("expected.json"), "{\"sphere\": []}");
        Files.write(c.resolve("framework.jar"), new byte[4096]);
        CacheManifest.write(c);
        return c;
    }

    static Stream<Arguments> poisonings() {
        return Stream.of(
                Arguments.of("a class file changed", (Poison) c -> Files.write(c.resolve("ref/sphere/raylab/surface/Sphere.class"),
                        new byte[] {(byte) 0xca, (byte) 0xfe, 1, 3}), "ref/sphere/raylab/surface/Sphere.class was changed"),
                Arguments.of("a file added", (Poison) c -> Files.writeString(c.resolve("canary.txt"), "x"),
                        "canary.txt is not in the manifest"),
                Arguments.of("a file removed (a partial cache)", (Poison) c -> Files.delete(c.resolve("framework.jar")),
                        "framework.jar is missing"),
                Arguments.of("a file replaced by a link", (Poison) c -> {
                    Files.delete(c.resolve("expected.json"));
                    Files.createSymbolicLink(c.resolve("expected.json"), Path.of("/etc/hostname"));
                }, "expected.json is a symbolic link"),
                Arguments.of("no manifest", (Poison) c -> Files.delete(c.resolve(CacheManifest.FILE)),
                        "no " + CacheManifest.FILE));
    }

    interface Poison {
        void apply(Path cache) throws IOException;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("poisonings")
    void aPoisonedCacheIsFoundAndNotUsed(String what, Poison poison, String expected) throws IOException {
        Path c = cache();
        assertEquals(Optional.empty(), CacheManifest.verify(c), "a fresh cache verifies");
        poison.apply(c);
        Optional<String> problem = CacheManifest.verify(c);
        assertTrue(problem.isPresent() && problem.get().contains(expected),
                what + ": expected a problem containing '" + expected + "', got " + problem);
        List<String> log = new ArrayList<>();
        assertFalse(CacheManifest.usable(c, log::add), "not used");
        assertFalse(Files.exists(c), "deleted, so that it is built again");
        assertEquals(1, log.size(), "one line says why: " + log);
        assertTrue(log.get(0).contains(expected), log.get(0));
    }

    @Test
    void theManifestIsSha256sumsFormat() throws IOException {
        Path c = cache();
        String m = Files.readString(c.resolve(CacheManifest.FILE), StandardCharsets.UTF_8);
        // sha256 of the 4096 zero bytes of framework.jar
        assertTrue(m.contains("ad7facb2586fc6e966c004d7d1d16b024f5805ff7cb47c7a85dabd8b48892ca7  framework.jar\n"), m);
        assertEquals(3, m.lines().count(), "one line per file, the manifest itself not listed: " + m);
        assertTrue(CacheManifest.usable(c, s -> { }), "a good cache is used");
        assertTrue(Files.isDirectory(c));
    }

    @Test
    void aCacheRewrittenWithItsManifestIsCaughtByTheGuard() throws IOException {
        Path c = cache();
        CacheManifest.Guard guard = CacheManifest.guard(c);
        // What a child running as the grader's user could do: change a class, then write a matching manifest.
        Files.write(c.resolve("ref/sphere/raylab/surface/Sphere.class"), new byte[] {1});
        CacheManifest.write(c);
        assertEquals(Optional.empty(), CacheManifest.verify(c), "the rewritten manifest matches");
        Optional<String> caught = guard.check();
        assertTrue(caught.isPresent() && caught.get().contains("was changed while this submission was graded"),
                "the guard compares with the manifest read at the start: " + caught);
        assertFalse(Files.exists(c), "deleted");
    }

    @Test
    void anUnchangedCachePassesTheGuard() throws IOException {
        Path c = cache();
        CacheManifest.Guard guard = CacheManifest.guard(c);
        assertEquals(Optional.empty(), guard.check());
        assertTrue(Files.isDirectory(c), "kept");
    }
}
