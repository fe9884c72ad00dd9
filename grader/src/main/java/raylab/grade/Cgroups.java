package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A control group per child where the grader may make one: cgroup v1 {@code pids} and
 * {@code cpu} hierarchies (under {@code /sys/fs/cgroup/<controller>/raylab/}), or cgroup v2 when
 * this process sits in a cgroup whose subtree it can delegate the two controllers to. Each child's
 * group allows {@link Sandbox#MAX_TASKS} tasks (threads and processes) and has the default CPU
 * weight: the kernel shares the CPU between the groups, not between threads, so a child with 1,000
 * busy threads gets no more CPU than one with ten. On one core or more, each group is also held
 * to one core's worth (CFS quota) so that the grader and the other child keep theirs. Nothing is
 * made where the files are not writable (an unprivileged grader, most containers): the
 * {@code prlimit} limits still hold.
 */
final class Cgroups {
    private static final Path ROOT = Path.of("/sys/fs/cgroup");

    private Cgroups() {
    }

    /** One child's groups: the folders made, and the {@code cgroup.procs} files to join. */
    record Group(List<Path> dirs) {
        /**
         * A command prefix that moves the command's own process into the groups and then runs
         * the rest ({@code exec}), so that the child and all it starts are in them from the start.
         */
        List<String> joinCommand() {
            List<String> cmd = new ArrayList<>(List.of("/bin/sh", "-c",
                    "while [ \"$1\" != -- ]; do echo $$ > \"$1\" || exit 125; shift; done; shift; exec \"$@\"",
                    "raylab-cgroup"));
            for (Path d : dirs) {
                cmd.add(d.resolve("cgroup.procs").toString());
            }
            cmd.add("--");
            return cmd;
        }

        /** The processes still in the groups. */
        List<Long> members() {
            List<Long> out = new ArrayList<>();
            for (Path d : dirs) {
                try {
                    for (String line : Files.readAllLines(d.resolve("cgroup.procs"))) {
                        if (!line.isBlank()) {
                            out.add(Long.parseLong(line.trim()));
                        }
                    }
                } catch (IOException | RuntimeException e) {
                    // gone
                }
            }
            return out;
        }

        /** How many times a task could not be made for the limit (v1 and v2 {@code pids.events}). */
        long tasksRefused() {
            for (Path d : dirs) {
                Path ev = d.resolve("pids.events");
                try {
                    for (String line : Files.readAllLines(ev)) {
                        if (line.startsWith("max ")) {
                            return Long.parseLong(line.substring(4).trim());
                        }
                    }
                } catch (IOException | RuntimeException e) {
                    // not this one
                }
            }
            return 0;
        }

        /** Removes the groups (they must be empty: the caller killed every member), a few tries. */
        void remove() {
            for (Path d : dirs) {
                for (int i = 0; i < 20 && Files.isDirectory(d); i++) {
                    try {
                        Files.delete(d);
                    } catch (IOException e) {
                        try {
                            Thread.sleep(25);
                        } catch (InterruptedException x) {
                            Thread.currentThread().interrupt();
                            return;
                        }
                    }
                }
            }
        }
    }

    /** Makes the groups for one child, or null when this machine lets the grader make none. */
    static Group create(String name, int maxTasks) {
        List<Path> made = new ArrayList<>();
        try {
            Path v2 = v2Parent();
            if (v2 != null) {
                Path d = v2.resolve(name);
                Files.createDirectory(d);
                made.add(d);
                write(d.resolve("pids.max"), Integer.toString(maxTasks));
                quota(d.resolve("cpu.max"), true);
                return new Group(made);
            }
            for (String controller : List.of("pids", "cpu")) {
                // Under this process's own group: a child stays within every limit the grader
                // itself is held to (a container's CPU quota, an emulated Gradescope cgroup).
                Path parent = ROOT.resolve(controller).resolve(ownV1(controller)).resolve("raylab");
                if (!Files.isRegularFile(ROOT.resolve(controller).resolve("cgroup.procs"))) {
                    continue;
                }
                try {
                    Files.createDirectories(parent);
                    removeStale(parent);
                    Path d = parent.resolve(name);
                    Files.createDirectory(d);
                    made.add(d);
                    if (controller.equals("pids")) {
                        write(d.resolve("pids.max"), Integer.toString(maxTasks));
                    } else {
                        quota(d.resolve("cpu.cfs_quota_us"), false);
                    }
                } catch (IOException e) {
                    // this controller is not ours to use
                }
            }
        } catch (IOException e) {
            // not writable: fall through
        }
        if (made.stream().noneMatch(d -> Files.isRegularFile(d.resolve("pids.max")))) {
            new Group(made).remove();
            return null;
        }
        return new Group(made);
    }

    /**
     * Groups a grader left when it was killed: empty (the kernel refuses to remove any other)
     * and older than ten minutes (a group another grading made a moment ago is still empty).
     */
    private static void removeStale(Path parent) {
        long old = System.currentTimeMillis() - 600_000;
        try (var s = Files.list(parent)) {
            for (Path d : (Iterable<Path>) s::iterator) {
                try {
                    if (d.getFileName().toString().startsWith("box") && Files.isDirectory(d)
                            && Files.getLastModifiedTime(d).toMillis() < old
                            && Files.readString(d.resolve("cgroup.procs")).isBlank()) {
                        Files.delete(d);
                    }
                } catch (IOException | RuntimeException e) {
                    // in use, or gone
                }
            }
        } catch (IOException e) {
            // nothing to clean
        }
    }

    /**
     * cgroup v1: the path of this process's group in the hierarchy of {@code controller}, relative
     * ("" at the root), from {@code /proc/self/cgroup} lines {@code N:controller[,...]:/path}.
     */
    static String ownV1(String controller) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/cgroup"))) {
                String[] f = line.split(":", 3);
                if (f.length == 3 && java.util.Arrays.asList(f[1].split(",")).contains(controller)) {
                    return f[2].replaceFirst("^/+", "");
                }
            }
        } catch (IOException | RuntimeException e) {
            // no /proc: the root
        }
        return "";
    }

    /** One core's worth per child where there are at least two (else only the fair share). */
    private static void quota(Path file, boolean v2) throws IOException {
        if (Runtime.getRuntime().availableProcessors() >= 2) {
            write(file, v2 ? "100000 100000" : "100000");
        }
    }

    private static void write(Path file, String value) throws IOException {
        Files.writeString(file, value + "\n", StandardCharsets.US_ASCII);
    }

    /**
     * cgroup v2: the group of this process, when pids and cpu can be enabled for its children.
     * The kernel forbids processes in a group whose controllers are delegated (except at the
     * root), so this works only at the root of the hierarchy or in a group prepared for it
     * (an empty {@code raylab} group with the controllers enabled, which is then used).
     */
    private static Path v2Parent() {
        if (!Files.isRegularFile(ROOT.resolve("cgroup.controllers"))) {
            return null;
        }
        try {
            String own = Files.readAllLines(Path.of("/proc/self/cgroup")).stream().filter(l -> l.startsWith("0::"))
                    .findFirst().orElse(null);
            if (own == null) {
                return null;
            }
            Path mine = ROOT.resolve(own.substring(3).replaceFirst("^/", ""));
            Path parent = own.substring(3).equals("/") ? ROOT.resolve("raylab") : mine;
            String controllers = Files.readString(mine.resolve("cgroup.controllers"));
            if (!controllers.contains("pids")) {
                return null;
            }
            if (!parent.equals(mine)) {
                Files.createDirectories(parent);
                String sub = Files.readString(mine.resolve("cgroup.subtree_control"));
                if (!sub.contains("pids")) {
                    write(mine.resolve("cgroup.subtree_control"), "+pids" + (controllers.contains("cpu") ? " +cpu" : ""));
                }
            }
            String sub = Files.readString(parent.resolve("cgroup.subtree_control"));
            if (!sub.contains("pids")) {
                write(parent.resolve("cgroup.subtree_control"), "+pids" + (controllers.contains("cpu") ? " +cpu" : ""));
            }
            return parent;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }
}
