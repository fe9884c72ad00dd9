package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.stream.Stream;

import raylab.course.JavaBuild;

/**
 * Where and as whom student code runs. Every child JVM that runs student code gets a private
 * folder, a {@link Box}: {@code cp/} holds read-only copies (or hard links) of exactly the class
 * path entries it needs, {@code run/} is its working directory, the only place it may write.
 * Three modes, the strongest available is chosen:
 * <ul>
 * <li>{@link Isolation#NAMESPACE} ({@code unshare} from util-linux works: root, or an unprivileged
 * user namespace): new network (no interface but a down loopback), mount, PID, IPC and UTS
 * namespaces; the child's root is an empty read-only tmpfs with only {@code /usr /bin /lib* /etc}
 * and the JDK bound read-only, four device nodes, no {@code /proc}, the box's class path at
 * {@code /box/cp} (read-only) and two private tmpfs of {@link #SCRATCH_SIZE} each (noexec):
 * {@code /box/run}, its working folder (its inputs copied in, the files it leaves copied back at
 * the end, see {@link #NS_SCRIPT}), and {@code /tmp}.
 * Every capability is dropped ({@code setpriv --bounding-set=-all --no-new-privs}); as root the
 * child also runs as the sandbox user (or {@code nobody}). The child JVM is PID 1 of its PID
 * namespace: when it ends or is killed, the kernel kills every process it left.</li>
 * <li>{@link Isolation#USER} (root, the sandbox user exists, but namespaces are not allowed, as in
 * Docker's default profile): the child runs as the sandbox user through {@code setpriv}; the box
 * is the only grader folder it can read (the grader's work folder is mode 711, the cache 700).</li>
 * <li>{@link Isolation#NONE}: the child runs as the grader's user, from its own copies.</li>
 * </ul>
 * As root (namespace and user modes) every child runs under a user id of its own
 * ({@link UidSlots}), and where cgroups can be written it is in a control group of its own
 * ({@link Cgroups}: {@link #MAX_TASKS} tasks, a fair CPU share).
 * In every mode: {@code prlimit} caps the file size (16 MiB), core dumps (0) and, unless the
 * child's real user is root, the number of processes; the child starts in its own session
 * ({@code setsid}) with a marker in its environment, and at the end its process group, its
 * descendants and every process of the grader's user or sandbox user that carries this box's
 * marker or runs from this box are killed (not all processes of a user: two gradings at once do
 * not kill each other's children).
 *
 * <p>One job: where and as whom student code runs; its three modes share one box layout and one
 * finishing step.
 */
final class Sandbox {
    /** The default name of the unprivileged user (created by the bundle's setup.sh and .ci/run). */
    static final String DEFAULT_USER = "raylab-student";
    /** Largest file a child may write (RLIMIT_FSIZE). */
    static final long MAX_FILE_BYTES = 16L << 20;
    /** Size of each of the child's two private tmpfs (namespace mode): its run folder and /tmp. */
    static final String SCRATCH_SIZE = "16m";
    /** {@link #SCRATCH_SIZE} in bytes. */
    static final long SCRATCH_BYTES = 16L << 20;
    /** Threads and processes one child may have at once (cgroup {@code pids.max}; RLIMIT_NPROC with its own uid). */
    static final int MAX_TASKS = 512;
    /** Exit status of a child stopped by the deadline of {@link Box#wrapper(java.time.Duration)}. */
    static final int DEADLINE_STATUS = 124;

    /** Isolation modes; AUTO picks the strongest available. */
    enum Isolation {
        AUTO, NAMESPACE, USER, NONE
    }

    /**
     * Runs inside the new namespaces as their PID 1 (root of the namespace, before the child
     * drops everything): builds the child's root, starts the child, and when it has ended kills
     * whatever it left and copies the regular files it left at the top of its run folder back to
     * the box's {@code run/} on the grader's side (at most {@link #SCRATCH_BYTES} in all: the
     * tmpfs holds no more). The run folder and {@code /tmp} are two tmpfs of
     * {@link #SCRATCH_SIZE} each, private to this child: nothing it writes reaches the grader's
     * disk while it runs, and a full disk is its own. A deadline (seconds, 0 for none) kills the
     * child from inside, so that what it wrote before is still copied back; the exit status is
     * then {@link #DEADLINE_STATUS}.
     */
    private static final String NS_SCRIPT = String.join("\n",
            "set -e",
            "R=\"$1\"; BOX=\"$2\"; JH=\"$3\"; U=\"$4\"; G=\"$5\"; D=\"$6\"; shift 6",
            "mount -t tmpfs -o size=1m,mode=755 raylab-root \"$R\"",
            "for d in /usr /bin /sbin /lib /lib32 /lib64 /libx32 /etc \"$JH\"; do",
            "  if [ ! -e \"$d\" ] && [ ! -L \"$d\" ]; then continue; fi",
            "  if [ -e \"$R$d\" ] || [ -L \"$R$d\" ]; then continue; fi",
            "  if [ -L \"$d\" ]; then ln -s \"$(readlink \"$d\")\" \"$R$d\"; continue; fi",
            "  mkdir -p \"$R$d\"; mount --bind \"$d\" \"$R$d\"; mount -o remount,bind,ro,nosuid \"$R$d\"",
            "done",
            "mkdir -p \"$R/dev\" \"$R/tmp\" \"$R/box/cp\" \"$R/box/run\"",
            "for n in null zero random urandom; do touch \"$R/dev/$n\"; mount --bind \"/dev/$n\" \"$R/dev/$n\"; done",
            "mount -t tmpfs -o size=" + SCRATCH_SIZE + ",mode=1777,nosuid,nodev,noexec raylab-tmp \"$R/tmp\"",
            "mount -t tmpfs -o size=" + SCRATCH_SIZE + ",mode=700,uid=\"$U\",gid=\"$G\",nosuid,nodev,noexec raylab-run \"$R/box/run\"",
            "cp -R \"$BOX/run/.\" \"$R/box/run/\"; chown -R \"$U:$G\" \"$R/box/run\"",
            "mount --bind \"$BOX/cp\" \"$R/box/cp\"; mount -o remount,bind,ro,nosuid,nodev,noexec \"$R/box/cp\"",
            "mount -o remount,bind,ro,nosuid,nodev \"$R\"",
            "set +e",
            "exec 3<&0",
            "unshare --root=\"$R\" --wd=/box/run \"$@\" 0<&3 3<&- &",
            "c=$!",
            "exec 3<&-",
            "if [ \"$D\" -gt 0 ]; then (sleep \"$D\"; : > \"$R.deadline\"; kill -KILL \"$c\") </dev/null >/dev/null 2>&1 & fi",
            "wait \"$c\"; rc=$?",
            "kill -KILL -1 2>/dev/null; wait 2>/dev/null",
            "for f in \"$R\"/box/run/*; do",
            "  n=\"${f##*/}\"",
            "  if [ -f \"$f\" ] && [ ! -L \"$f\" ] && [ ! -e \"$BOX/run/$n\" ] && [ ! -L \"$BOX/run/$n\" ]; then",
            "    head -c " + SCRATCH_BYTES + " \"$f\" > \"$BOX/run/$n\"",
            "  fi",
            "done",
            "if [ -e \"$R.deadline\" ]; then rc=" + DEADLINE_STATUS + "; fi",
            "exit $rc");

    private final Isolation mode;
    private final String user;
    private final int uid;
    private final int gid;
    private final boolean root;
    private final Path unshare;
    private final Path setpriv;
    private final Path prlimit;
    private final Path setsid;

    private Sandbox(Isolation mode, String user, int uid, int gid, boolean root) {
        this.mode = mode;
        this.user = user;
        this.uid = uid;
        this.gid = gid;
        this.root = root;
        this.unshare = tool("unshare");
        this.setpriv = tool("setpriv");
        this.prlimit = tool("prlimit");
        this.setsid = tool("setsid");
    }

    /** No isolation beyond private copies: children run as this process's user. */
    static Sandbox none() {
        return new Sandbox(Isolation.NONE, null, -1, -1, isRoot());
    }

    Isolation mode() {
        return mode;
    }

    /** Whether student code runs as another user than the grader. */
    boolean active() {
        return user != null;
    }

    String user() {
        return user;
    }

    /** What is and is not isolated in this mode, one line for the report. */
    String describe() {
        return switch (mode) {
            case NAMESPACE -> "sandbox: namespaces (no network, private /tmp and file tree, PID namespace"
                    + (user == null ? ", all capabilities dropped" : ", user " + user) + ")";
            case USER -> "sandbox: user " + user + " without namespaces (not isolated: network, the shared /tmp)";
            default -> "sandbox: none (student code runs as " + System.getProperty("user.name")
                    + "; not isolated: network, /tmp, the grader's files; children still get private copies"
                    + " and are killed at the end)";
        };
    }

    /**
     * The sandbox for this process. {@code userName}: the unprivileged user (null: default,
     * "": none); {@code wanted}: AUTO or a forced mode (a forced mode that cannot work falls back
     * to a weaker one, logged). {@code log} receives one line saying which mode is used.
     */
    static Sandbox detect(String userName, Isolation wanted, Consumer<String> log) {
        boolean isRoot = isRoot();
        String name = userName == null ? DEFAULT_USER : userName;
        Optional<int[]> ids = name.isEmpty() ? Optional.empty() : lookup(name);
        Isolation want = wanted == null ? Isolation.AUTO : wanted;
        Sandbox s;
        if ((want == Isolation.AUTO || want == Isolation.NAMESPACE) && namespacesWork(isRoot)) {
            if (isRoot) {
                int[] id = ids.orElse(new int[] {65534, 65534});
                s = new Sandbox(Isolation.NAMESPACE, ids.isPresent() ? name : "nobody", id[0], id[1], true);
            } else {
                s = new Sandbox(Isolation.NAMESPACE, null, -1, -1, false);
            }
        } else if ((want == Isolation.AUTO || want == Isolation.NAMESPACE || want == Isolation.USER) && isRoot && ids.isPresent()
                && tool("setpriv") != null) {
            s = new Sandbox(Isolation.USER, name, ids.get()[0], ids.get()[1], true);
        } else {
            s = none();
            if (isRoot && want != Isolation.NONE) {
                log.accept("sandbox: running as root but " + (ids.isEmpty() ? "there is no user '" + name
                        + "' (create it: useradd -M -s /usr/sbin/nologin " + name + ")" : "setpriv is missing")
                        + " and namespaces are not available");
            }
        }
        log.accept(s.describe());
        return s;
    }

    private static Boolean namespaceProbe;

    /** Whether {@code unshare} can create the namespaces (tried once per JVM). */
    static synchronized boolean namespacesWork(boolean isRoot) {
        if (namespaceProbe == null) {
            Path u = tool("unshare");
            boolean ok = false;
            if (u != null && tool("setpriv") != null) {
                List<String> cmd = new ArrayList<>(List.of(u.toString()));
                if (!isRoot) {
                    cmd.addAll(List.of("--user", "--map-root-user"));
                }
                cmd.addAll(List.of("--net", "--mount", "--pid", "--ipc", "--uts", "--fork", "--kill-child", "sh", "-c",
                        "mount -t tmpfs raylab-probe /mnt && echo ok"));
                try {
                    Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
                    String out = new String(p.getInputStream().readNBytes(256), StandardCharsets.UTF_8);
                    ok = p.waitFor(20, TimeUnit.SECONDS) && p.exitValue() == 0 && out.contains("ok");
                    p.destroyForcibly();
                } catch (IOException e) {
                    ok = false;
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            namespaceProbe = ok;
        }
        return namespaceProbe;
    }

    static Path tool(String name) {
        return Stream.of("/usr/bin/", "/bin/", "/usr/sbin/", "/sbin/").map(d -> Path.of(d + name))
                .filter(Files::isExecutable).findFirst().orElse(null);
    }

    static boolean isRoot() {
        try {
            Object uid = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
            return Integer.valueOf(0).equals(uid);
        } catch (Exception e) {
            return "root".equals(System.getProperty("user.name"));
        }
    }

    private static Optional<int[]> lookup(String name) {
        try {
            for (String line : Files.readAllLines(Path.of("/etc/passwd"))) {
                String[] f = line.split(":");
                if (f.length > 3 && f[0].equals(name)) {
                    return Optional.of(new int[] {Integer.parseInt(f[2]), Integer.parseInt(f[3])});
                }
            }
        } catch (IOException | NumberFormatException e) {
            // no passwd file: no such user
        }
        return Optional.empty();
    }

    /**
     * One child's private folder.
     *
     * @param dir       the box on the grader's side
     * @param run       its working directory on the grader's side
     * @param classPath the class path as the child sees it
     * @param marker    the random marker in the child's environment
     * @param uid       the child's user id (its own, when the grader is root and a range is free), -1: the grader's
     * @param gid       the child's group id, -1: the grader's
     * @param slot      the lock that reserves {@code uid} for this box (null: no own uid)
     * @param cgroup    the box's control groups (null: none could be made)
     */
    record Box(Path dir, Path run, List<String> classPath, String marker, Sandbox sandbox, int uid, int gid,
            UidSlots.Slot slot, Cgroups.Group cgroup) {
        /** A path inside {@code cp/} or {@code run/} as the child sees it. */
        String inChild(Path hostPath) {
            return sandbox.mode == Isolation.NAMESPACE ? "/box/" + dir.relativize(hostPath).toString().replace('\\', '/')
                    : hostPath.toString();
        }

        /** The command prefix that starts a program in this box. */
        List<String> wrapper() {
            return sandbox.wrapper(this, null);
        }

        /**
         * As {@link #wrapper()}, with a deadline enforced inside the sandbox (namespace mode): the
         * child is killed when it is reached, what it wrote to its run folder is still copied
         * back, and the exit status is {@link Sandbox#DEADLINE_STATUS}. Give the process a little
         * longer than this on the grader's side.
         */
        List<String> wrapper(java.time.Duration deadline) {
            return sandbox.wrapper(this, deadline);
        }

        /** Whether the child runs under an id no other child has (so it can be cleaned up by it). */
        boolean ownUid() {
            return slot != null;
        }
    }

    /**
     * Makes a box under {@code parent}: {@code cp/<i>} for each class path entry (directories
     * copied, files linked when the child cannot write them, else copied; {@code filter} chooses
     * which files of a directory entry to take), and {@code run/}. As root, the box reserves a
     * user id of its own ({@link UidSlots}); where cgroups can be written it gets a control group
     * with {@link #MAX_TASKS} tasks and a fair CPU share ({@link Cgroups}). {@link #finish} frees both.
     */
    Box box(Path parent, List<Path> classPath, java.util.function.BiPredicate<Path, String> filter) throws IOException {
        Path dir = Files.createTempDirectory(parent, "box");
        Path cp = Files.createDirectories(dir.resolve("cp"));
        Path run = Files.createDirectories(dir.resolve("run"));
        Files.createDirectories(run.resolve("tmp"));
        Files.createDirectories(dir.resolveSibling(dir.getFileName() + "-root"));
        List<String> inside = new ArrayList<>();
        boolean link = mode != Isolation.NONE;
        for (int i = 0; i < classPath.size(); i++) {
            Path from = classPath.get(i);
            Path to = cp.resolve(i + (Files.isDirectory(from) ? "" : "-" + from.getFileName()));
            if (Files.isDirectory(from)) {
                try (Stream<Path> w = Files.walk(from)) {
                    for (Path p : (Iterable<Path>) w::iterator) {
                        String rel = from.relativize(p).toString().replace('\\', '/');
                        Path q = to.resolve(rel);
                        if (Files.isDirectory(p)) {
                            Files.createDirectories(q);
                        } else if (Files.isRegularFile(p) && filter.test(from, rel)) {
                            Files.createDirectories(q.getParent());
                            Files.copy(p, q);
                        }
                    }
                }
            } else if (Files.isRegularFile(from)) {
                if (!filter.test(from, "")) {
                    continue;
                }
                boolean linked = false;
                if (link) {
                    try {
                        Files.createLink(to, from);
                        linked = true;
                    } catch (IOException | UnsupportedOperationException e) {
                        linked = false;
                    }
                }
                if (!linked) {
                    Files.copy(from, to);
                }
            } else {
                continue;
            }
            inside.add(mode == Isolation.NAMESPACE ? "/box/cp/" + to.getFileName() : to.toString());
        }
        // Its own user id: as root with a sandbox user (namespace or user mode), from the free range.
        UidSlots.Slot slot = user != null && root ? UidSlots.reserve() : null;
        int childUid = slot != null ? slot.uid() : user != null ? uid : -1;
        int childGid = slot != null ? slot.uid() : user != null ? gid : -1;
        Cgroups.Group cg = Cgroups.create(dir.getFileName().toString(), MAX_TASKS);
        Box b = new Box(dir, run, inside, HexFormat.of().formatHex(random(12)), this, childUid, childGid, slot, cg);
        prepare(b);
        return b;
    }

    /** Permissions: the box readable by the child, run/ writable by it, nothing else. */
    private void prepare(Box b) throws IOException {
        try {
            if (mode == Isolation.NONE) {
                return;
            }
            try (Stream<Path> s = Files.walk(b.dir().resolve("cp"))) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    if (!Files.isSymbolicLink(p) && !(Files.isRegularFile(p) && Files.getAttribute(p, "unix:nlink")
                            instanceof Integer n && n > 1)) {
                        Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(
                                Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
                    }
                }
            }
            Files.setPosixFilePermissions(b.dir(), PosixFilePermissions.fromString("rwxr-xr-x"));
            if (b.uid() >= 0) {
                try (Stream<Path> s = Files.walk(b.run())) {
                    for (Path p : (Iterable<Path>) s::iterator) {
                        Files.setAttribute(p, "unix:uid", b.uid(), java.nio.file.LinkOption.NOFOLLOW_LINKS);
                        Files.setAttribute(p, "unix:gid", b.gid(), java.nio.file.LinkOption.NOFOLLOW_LINKS);
                    }
                }
            }
            Files.setPosixFilePermissions(b.run(), PosixFilePermissions.fromString("rwx------"));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system
        }
    }

    /** Makes a grader tree readable (not writable) by others, file by file. */
    static void readableByAll(Path root) throws IOException {
        try (Stream<Path> s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (!Files.isSymbolicLink(p)) {
                    Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(
                            Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
                }
            }
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system
        }
    }

    /** Only the owner may enter the folder. */
    static void privateFolder(Path dir) throws IOException {
        try {
            Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
        } catch (UnsupportedOperationException e) {
            // not POSIX
        }
    }

    /** The grader's work folder: traversable by the child (to reach its box), not listable. */
    static void workFolder(Path work) throws IOException {
        try {
            Files.setPosixFilePermissions(work, PosixFilePermissions.fromString("rwx--x--x"));
        } catch (UnsupportedOperationException e) {
            // not POSIX
        }
    }

    private List<String> wrapper(Box b, java.time.Duration deadline) {
        List<String> cmd = new ArrayList<>();
        if (b.cgroup() != null) {
            cmd.addAll(b.cgroup().joinCommand());
        }
        if (prlimit != null) {
            cmd.addAll(List.of(prlimit.toString(), "--fsize=" + MAX_FILE_BYTES, "--core=0"));
            int nproc = processLimit(b);
            if (nproc > 0) {
                cmd.add("--nproc=" + nproc);
            }
            cmd.add("--");
        }
        if (mode == Isolation.NAMESPACE) {
            cmd.add(unshare.toString());
            if (!root) {
                cmd.addAll(List.of("--user", "--map-root-user"));
            }
            long seconds = deadline == null ? 0 : Math.max(1, deadline.toSeconds());
            cmd.addAll(List.of("--net", "--mount", "--pid", "--ipc", "--uts", "--fork", "--kill-child", "--", "sh", "-c",
                    NS_SCRIPT, "raylab-sandbox", b.dir().resolveSibling(b.dir().getFileName() + "-root").toString(),
                    b.dir().toString(), javaHome(), Integer.toString(Math.max(0, b.uid())),
                    Integer.toString(Math.max(0, b.gid())), Long.toString(seconds)));
            cmd.add(setpriv.toString());
            if (b.uid() >= 0) {
                cmd.addAll(List.of("--reuid=" + b.uid(), "--regid=" + b.gid(), "--clear-groups"));
            }
            cmd.addAll(List.of("--bounding-set=-all", "--inh-caps=-all", "--no-new-privs", "--",
                    "/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "HOME=/box/run", "TMPDIR=/tmp", "LANG=C.UTF-8",
                    "LD_LIBRARY_PATH=" + javaHome() + "/lib", "RAYLAB_BOX=" + b.marker()));
            return cmd;
        }
        if (setsid != null) {
            cmd.add(setsid.toString());
        }
        if (mode == Isolation.USER) {
            cmd.addAll(List.of(setpriv.toString(), "--reuid=" + b.uid(), "--regid=" + b.gid(), "--clear-groups",
                    "--no-new-privs", "--"));
        }
        cmd.addAll(List.of("/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "HOME=" + b.run(), "TMPDIR=" + b.run().resolve("tmp"),
                "LANG=C.UTF-8", "RAYLAB_BOX=" + b.marker()));
        return cmd;
    }

    /**
     * RLIMIT_NPROC counts every process of the real user: with a user id of its own the child
     * gets {@link #MAX_TASKS}; with a shared one its share on top of what runs now.
     */
    private int processLimit(Box b) {
        if (b.ownUid()) {
            return MAX_TASKS;
        }
        int childUid = b.uid() >= 0 ? b.uid() : root ? 0 : currentUid();
        if (childUid == 0 || childUid < 0) {
            return 0; // root is exempt from RLIMIT_NPROC
        }
        return countThreadsOf(childUid) + MAX_TASKS;
    }

    private static int currentUid() {
        try {
            return (Integer) Files.getAttribute(Path.of("/proc/self"), "unix:uid");
        } catch (Exception e) {
            return -1;
        }
    }

    private static int countThreadsOf(int uid) {
        int n = 0;
        try (Stream<Path> s = Files.list(Path.of("/proc"))) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String f = p.getFileName().toString();
                if (!f.chars().allMatch(Character::isDigit)) {
                    continue;
                }
                try {
                    if (Integer.valueOf(uid).equals(Files.getAttribute(p, "unix:uid"))) {
                        try (Stream<Path> t = Files.list(p.resolve("task"))) {
                            n += (int) t.count();
                        }
                    }
                } catch (IOException | RuntimeException e) {
                    // the process ended meanwhile
                }
            }
        } catch (IOException e) {
            return 4096;
        }
        return n;
    }

    static String javaHome() {
        try {
            return Path.of(System.getProperty("java.home")).toRealPath().toString();
        } catch (IOException e) {
            return System.getProperty("java.home");
        }
    }

    private static byte[] random(int n) {
        byte[] b = new byte[n];
        new SecureRandom().nextBytes(b);
        return b;
    }

    /**
     * Ends everything the box's child left and deletes the box. In namespace mode the kernel
     * already killed the PID namespace; otherwise the box's process group and every process of
     * the child's user that carries the box's marker or runs from the box are killed, a few
     * rounds (a process forking meanwhile is caught in the next).
     */
    void finish(Box b, Process p) {
        if (p != null) {
            JavaBuild.stop(p);
        }
        for (int round = 0; round < 3; round++) {
            List<ProcessHandle> left = leftovers(b);
            if (b.cgroup() != null) {
                b.cgroup().members().forEach(pid -> ProcessHandle.of(pid).ifPresent(left::add));
            }
            if (left.isEmpty()) {
                break;
            }
            left.forEach(ProcessHandle::destroyForcibly);
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        if (b.cgroup() != null) {
            b.cgroup().remove();
        }
        if (b.ownUid()) {
            // Whatever the child left in the shared writable places (user mode; in namespace mode
            // it never saw them).
            if (mode != Isolation.NAMESPACE) {
                UidSlots.removeFilesOf(b.uid());
            }
            b.slot().release();
        }
        JavaBuild.deleteTreeQuietly(b.dir());
        Path rootDir = b.dir().resolveSibling(b.dir().getFileName() + "-root");
        JavaBuild.deleteTreeQuietly(rootDir);
        try {
            Files.deleteIfExists(Path.of(rootDir + ".deadline"));
        } catch (IOException e) {
            // best effort
        }
    }

    /** Processes that belong to this box (marker in the environment, or command line or folder in it). */
    List<ProcessHandle> leftovers(Box b) {
        List<ProcessHandle> out = new ArrayList<>();
        long self = ProcessHandle.current().pid();
        String marker = "RAYLAB_BOX=" + b.marker();
        String dir = b.dir().toString();
        try (Stream<Path> s = Files.list(Path.of("/proc"))) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String f = p.getFileName().toString();
                if (!f.chars().allMatch(Character::isDigit) || Long.parseLong(f) == self) {
                    continue;
                }
                try {
                    boolean mine = b.ownUid() && Integer.valueOf(b.uid()).equals(Files.getAttribute(p, "unix:uid"));
                    if (!mine) {
                        mine = new String(Files.readAllBytes(p.resolve("environ")), StandardCharsets.ISO_8859_1)
                                .contains(marker);
                    }
                    if (!mine) {
                        mine = new String(Files.readAllBytes(p.resolve("cmdline")), StandardCharsets.ISO_8859_1)
                                .contains(dir);
                    }
                    if (!mine) {
                        try {
                            mine = Files.readSymbolicLink(p.resolve("cwd")).toString().startsWith(dir);
                        } catch (IOException e) {
                            mine = false;
                        }
                    }
                    if (mine) {
                        ProcessHandle.of(Long.parseLong(f)).ifPresent(out::add);
                    }
                } catch (IOException | RuntimeException e) {
                    // not ours to read, or gone
                }
            }
        } catch (IOException e) {
            // no /proc: nothing more can be found
        }
        return out;
    }
}
