package raylab.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

import picocli.CommandLine.TypeConversionException;

/**
 * {@link ClassScale}: the shards of a folder cover every submission exactly once and differ in
 * size by at most one (seeded random classes), {@code --shard} is read strictly, the default
 * {@code --jobs} follows cores and memory, and the lock is exclusive until released.
 */
class ClassScaleTest {
    @TempDir
    Path dir;

    @TestFactory
    Stream<DynamicTest> theShardsCoverEverySubmissionOnce() {
        long seed = 36_08L;
        Random r = new Random(seed);
        return IntStream.range(0, 40).mapToObj(i -> {
            int size = r.nextInt(300);
            int n = 1 + r.nextInt(16);
            return DynamicTest.dynamicTest("seed " + seed + " #" + i + ": " + size + " submissions, " + n + " shards", () -> {
                Map<String, Integer> all = new TreeMap<>();
                for (int s = 0; s < size; s++) {
                    all.put("student" + Long.toString(r.nextLong() & Long.MAX_VALUE, 36), s);
                }
                List<String> seen = new ArrayList<>();
                int min = Integer.MAX_VALUE;
                int max = 0;
                for (int k = 1; k <= n; k++) {
                    Map<String, Integer> part = new ClassScale.Shard(k, n).of(all);
                    seen.addAll(part.keySet());
                    min = Math.min(min, part.size());
                    max = Math.max(max, part.size());
                }
                assertEquals(all.size(), seen.size(), "seed " + seed + ": every submission in exactly one shard");
                assertEquals(all.keySet(), new HashSet<>(seen), "seed " + seed + ": the same submissions");
                assertTrue(max - min <= 1, "seed " + seed + ": shard sizes " + min + " to " + max);
            });
        });
    }

    @Test
    void shardOptionIsReadStrictly() {
        ClassScale.ShardConverter c = new ClassScale.ShardConverter();
        assertEquals(new ClassScale.Shard(3, 8), c.convert("3/8"));
        assertEquals(new ClassScale.Shard(1, 1), c.convert("1/1"));
        for (String bad : List.of("0/2", "3/2", "2", "a/b", "1/0", "-1/2", "1/2/3", "")) {
            TypeConversionException e = assertThrows(TypeConversionException.class, () -> c.convert(bad), bad);
            assertTrue(e.getMessage().startsWith("--shard: "), e.getMessage());
        }
    }

    @Test
    void jobsFollowCoresAndMemory() {
        long gb = 1L << 30;
        assertEquals(2, ClassScale.jobsFor(2, 24 * gb), "2 cores, plenty of memory");
        assertEquals(16, ClassScale.jobsFor(16, 64 * gb));
        assertEquals(5, ClassScale.jobsFor(16, 4 * gb), "4 GB hold 5 gradings of 768 MB");
        assertEquals(1, ClassScale.jobsFor(8, 100L << 20), "never fewer than one");
        assertEquals(4, ClassScale.jobsFor(4, -1), "memory unknown: the cores");
        assertTrue(ClassScale.defaultJobs() >= 1 && ClassScale.defaultJobs() <= Runtime.getRuntime().availableProcessors());
    }

    @Test
    void theLockIsExclusiveUntilReleased() throws Exception {
        Path f = dir.resolve("x.lock");
        try (ClassScale.Lock a = ClassScale.Lock.tryTake(f)) {
            assertNotNull(a);
            assertNull(ClassScale.Lock.tryTake(f), "held: refused");
            assertNull(ClassScale.Lock.take(f, 300), "held: refused after waiting");
        }
        try (ClassScale.Lock b = ClassScale.Lock.tryTake(f)) {
            assertNotNull(b, "released: taken again");
        }
    }
}
