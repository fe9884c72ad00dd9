package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The limits of one child (namespace mode): a private scratch space of 16 MB that fills up
 * without touching the grader's disk, nothing shared between two children running at once, a
 * user id of its own, a task limit, and a deadline after which what it wrote is still handed
 * back. The children here are shell scripts (no JVM), so these tests take seconds.
 */
class SandboxLimitsTest {
    @TempDir
    Path dir;

    private static Sandbox namespace() {
        assumeTrue(Sandbox.namespacesWork(Sandbox.isRoot()), "unshare cannot create namespaces here");
        return Sandbox.detect("", Sandbox.Isolation.NAMESPACE, s -> { });
    }

    /** A child running {@code script} in {@code box}; output and error together. */
    private static Process start(Sandbox.Box box, Duration deadline, String script) throws IOException {
        List<String> cmd = new ArrayList<>(deadline == null ? box.wrapper() : box.wrapper(deadline));
        cmd.addAll(List.of("/bin/sh", "-c", script));
        return new ProcessBuilder(cmd).directory(box.run().toFile()).redirectErrorStream(true).start();
    }

    private static String finish(Process p, int seconds) throws Exception {
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(seconds, TimeUnit.SECONDS), "the child ended; it printed: " + out);
        return out;
    }

    private Sandbox.Box box(Sandbox s, String name) throws IOException {
        Path parent = Files.createDirectories(dir.resolve(name));
        Sandbox.workFolder(parent);
        return s.box(parent, List.of(), (e, r) -> true);
    }

    @Test
    void aFullScratchSpaceIsTheChildsOwnFailure() throws Exception {
        Sandbox s = namespace();
        Sandbox.Box b = box(s, "full");
        long freeBefore = Files.getFileStore(dir).getUsableSpace();
        try {
            // Files of 1 MB each: the space runs out, not the file size limit (also 16 MB).
            String out = finish(start(b, null, "for d in . /tmp; do i=0; while [ $i -lt 40 ]; do "
                    + "dd if=/dev/zero of=$d/big$i bs=1M count=1 2>&1 | grep -m1 'No space' && break; i=$((i+1)); done; done;"
                    + " echo done"), 60);
            assertEquals(2, out.split("No space left on device", -1).length - 1,
                    "both the run folder and /tmp are full at 16 MB; the child printed: " + out);
            assertTrue(out.contains("done"), out);
            long back = 0;
            try (var files = Files.list(b.run())) {
                for (Path f : (Iterable<Path>) files::iterator) {
                    back += Files.isRegularFile(f) ? Files.size(f) : 0;
                }
            }
            assertTrue(Files.isRegularFile(b.run().resolve("big0")), "what the child wrote is handed back");
            assertTrue(back <= Sandbox.SCRATCH_BYTES, "at most 16 MB handed back: " + back);
            assertFalse(Files.exists(b.run().resolve("tmp/big0")), "/tmp is not the box's");
        } finally {
            s.finish(b, null);
        }
        long freeAfter = Files.getFileStore(dir).getUsableSpace();
        // Other builds share this disk: allow them 1 GB of noise, far less than 80 MB would show... so
        // compare only that the box itself is gone.
        assertFalse(Files.exists(b.dir()), "box removed (free before " + freeBefore + ", after " + freeAfter + ")");
    }

    @Test
    void twoChildrenAtOnceShareNoWritablePlace() throws Exception {
        Sandbox s = namespace();
        Sandbox.Box a = box(s, "a");
        Sandbox.Box b = box(s, "b");
        try {
            Process pa = start(a, null, "echo secret-a > /tmp/tag-a; echo secret-a > tag-a; echo $(id -u) > /tmp/uid;"
                    + " touch /dev/shm/tag-a 2>/dev/null; sleep 3; echo a-done");
            Thread.sleep(1000);
            String outB = finish(start(b, null, "cat /tmp/tag-a /box/run/tag-a /dev/shm/tag-a 2>&1;"
                    + " ls -a /tmp /box/run 2>&1; find / -name 'tag-a*' 2>/dev/null; echo uid=$(id -u)"), 30);
            String outA = finish(pa, 30);
            assertTrue(outA.contains("a-done"), outA);
            assertFalse(outB.contains("secret-a"), "B cannot read what A wrote: " + outB);
            assertFalse(outB.matches("(?s).*/tag-a\\b.*") && !outB.contains("No such file"),
                    "B finds none of A's files: " + outB);
            assertTrue(outB.contains("uid=" + b.uid()), "B runs as its own uid " + b.uid() + ": " + outB);
            assertNotEquals(a.uid(), b.uid(), "each child its own uid");
            assertTrue(a.uid() >= UidSlots.BASE && a.uid() < UidSlots.BASE + UidSlots.COUNT,
                    "from the range: " + a.uid());
        } finally {
            s.finish(a, null);
            s.finish(b, null);
        }
    }

    @Test
    void aThousandTasksAreRefusedAtTheLimit() throws Exception {
        Sandbox s = namespace();
        Sandbox.Box b = box(s, "tasks");
        try {
            // The shell gives up at the first fork that fails; the count it wrote is handed back.
            String out = finish(start(b, null, "i=0; while [ $i -lt 1000 ]; do sleep 60 & i=$((i+1)); echo $i > count; done"),
                    60);
            int started = Integer.parseInt(Files.readString(b.run().resolve("count")).strip());
            assertTrue(started > 100 && started < Sandbox.MAX_TASKS, "stopped by the limit of " + Sandbox.MAX_TASKS
                    + " tasks: started " + started + " of 1000 (the shell printed: " + out + ")");
        } finally {
            s.finish(b, null);
        }
        assertTrue(ProcessHandle.allProcesses().noneMatch(h -> h.info().user().orElse("").equals(Integer.toString(b.uid()))),
                "nothing of the child's uid left");
    }

    @Test
    void theDeadlineStopsTheChildAndKeepsWhatItWrote() throws Exception {
        Sandbox s = namespace();
        Sandbox.Box b = box(s, "deadline");
        try {
            long t0 = System.nanoTime();
            Process p = start(b, Duration.ofSeconds(2), "echo partial > out.txt; sleep 30; echo never > late.txt");
            finish(p, 20);
            double seconds = (System.nanoTime() - t0) / 1e9;
            assertEquals(Sandbox.DEADLINE_STATUS, p.exitValue(), "the deadline's exit status");
            assertTrue(seconds < 15, "stopped at the deadline, not after the sleep: " + seconds + " s");
            assertEquals("partial\n", Files.readString(b.run().resolve("out.txt")), "what it wrote before is kept");
            assertFalse(Files.exists(b.run().resolve("late.txt")));
        } finally {
            s.finish(b, null);
        }
    }

    @Test
    void theExitStatusAndInputReachTheChild() throws Exception {
        Sandbox s = namespace();
        Sandbox.Box b = box(s, "io");
        Files.writeString(b.run().resolve("input.txt"), "given");
        try {
            List<String> cmd = new ArrayList<>(b.wrapper());
            cmd.addAll(List.of("/bin/sh", "-c", "read line; echo \"got $line $(cat input.txt)\"; exit 7"));
            Process p = new ProcessBuilder(cmd).directory(b.run().toFile()).redirectErrorStream(true).start();
            p.getOutputStream().write("key\n".getBytes(StandardCharsets.UTF_8));
            p.getOutputStream().flush();
            String out = finish(p, 30);
            assertEquals("got key given", out.strip(), "standard input and the run folder's files reach the child");
            assertEquals(7, p.exitValue(), "its exit status comes back");
        } finally {
            s.finish(b, null);
        }
    }

    @Test
    void filesOfTheChildsUidAreRemovedFromSharedPlaces() throws Exception {
        assumeTrue(Sandbox.isRoot(), "only root can give a file another owner");
        UidSlots.Slot slot = UidSlots.reserve();
        assertNotNull(slot, "a uid of the range is free");
        try {
            Path shared = Files.createDirectories(dir.resolve("shared"));
            Files.setPosixFilePermissions(shared, java.nio.file.attribute.PosixFilePermissions.fromString("rwxrwxrwx"));
            Path theirs = Files.writeString(shared.resolve("left-by-child"), "x");
            Path folder = Files.createDirectories(shared.resolve("child-folder"));
            Files.writeString(folder.resolve("inside"), "y");
            Path mine = Files.writeString(shared.resolve("someone-else"), "z");
            for (Path p : List.of(theirs, folder, folder.resolve("inside"))) {
                Files.setAttribute(p, "unix:uid", slot.uid(), java.nio.file.LinkOption.NOFOLLOW_LINKS);
            }
            UidSlots.removeOwned(shared, slot.uid());
            assertFalse(Files.exists(theirs), "the child's file removed");
            assertFalse(Files.exists(folder), "the child's folder removed");
            assertTrue(Files.exists(mine), "another user's file kept");
        } finally {
            slot.release();
        }
    }
}
