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

/**
 * Where and as whom student code runs. Every child JVM that runs student code gets a private
 * folder, a {@link Box}: {@code cp/} holds read-only copies (or hard links) of exactly the class
 * path entries it needs, {@code run/} is its working directory, the only place it may write.
 * Three modes, the strongest available is chosen:
 * <ul>
 * <li>{@link Mode#NAMESPACE} ({@code unshare} from util-linux works: root, or an unprivileged
 * user namespace): new network (no interface but a down loopback), mount, PID, IPC and UTS
 * namespaces; the child's root is an empty read-only tmpfs with only {@code /usr /bin /lib* /etc}
 * and the JDK bound read-only, four device nodes, no {@code /proc}, a private 64 MiB
 * {@code /tmp} (noexec), and the box at {@code /box} ({@code cp} read-only, all of it noexec).
 * Every capability is dropped ({@code setpriv --bounding-set=-all --no-new-privs}); as root the
 * child also runs as the sandbox user (or {@code nobody}). The child JVM is PID 1 of its PID
 * namespace: when it ends or is killed, the kernel kills every process it left.</li>
 * <li>{@link Mode#USER} (root, the sandbox user exists, but namespaces are not allowed, as in
 * Docker's default profile): the child runs as the sandbox user through {@code setpriv}; the box
 * is the only grader folder it can read (the grader's work folder is mode 711, the cache 700).</li>
 * <li>{@link Mode#NONE}: the child runs as the grader's user, from its own copies.</li>
 * </ul>
 * In every mode: {@code prlimit} caps the file size (64 MiB), core dumps (0) and, unless the
 * child's real user is root, the number of processes; the child starts in its own session
 * ({@code setsid}) with a marker in its environment, and at the end its process group, its
 * descendants and every process of the grader's user or sandbox user that carries this box's
 * marker or runs from this box are killed (not all processes of a user: two gradings at once do
 * not kill each other's children).
 */
final class Sandbox {
    /** The default name of the unprivileged user (created by the bundle's setup.sh and .ci/run). */
    static final String DEFAULT_USER = "raylab-student";
    /** Largest file a child may write. */
    static final long MAX_FILE_BYTES = 64L << 20;
    /** Size of the child's private /tmp (namespace mode). */
    static final String TMP_SIZE = "64m";

    /** Isolation modes; AUTO picks the strongest available. */
    enum Mode {
        AUTO, NAMESPACE, USER, NONE
    }

    private static final String NS_SCRIPT = String.join("\n",
            "set -e",
            "R=\"$1\"; BOX=\"$2\"; JH=\"$3\"; shift 3",
            "mount -t tmpfs -o size=1m,mode=755 raylab-root \"$R\"",
            "for d in /usr /bin /sbin /lib /lib32 /lib64 /libx32 /etc \"$JH\"; do",
            "  if [ ! -e \"$d\" ] && [ ! -L \"$d\" ]; then continue; fi",
            "  if [ -e \"$R$d\" ] || [ -L \"$R$d\" ]; then continue; fi",
            "  if [ -L \"$d\" ]; then ln -s \"$(readlink \"$d\")\" \"$R$d\"; continue; fi",
            "  mkdir -p \"$R$d\"; mount --bind \"$d\" \"$R$d\"; mount -o remount,bind,ro,nosuid \"$R$d\"",
            "done",
            "mkdir -p \"$R/dev\" \"$R/tmp\" \"$R/box\"",
            "for n in null zero random urandom; do touch \"$R/dev/$n\"; mount --bind \"/dev/$n\" \"$R/dev/$n\"; done",
            "mount -t tmpfs -o size=" + TMP_SIZE + ",mode=1777,nosuid,nodev,noexec raylab-tmp \"$R/tmp\"",
            "mount --bind \"$BOX\" \"$R/box\"; mount -o remount,bind,nosuid,nodev,noexec \"$R/box\"",
            "mount --bind \"$BOX/cp\" \"$R/box/cp\"; mount -o remount,bind,ro,nosuid,nodev,noexec \"$R/box/cp\"",
            "mount -o remount,bind,ro,nosuid,nodev \"$R\"",
            "exec unshare --root=\"$R\" --wd=/box/run \"$@\"");

    private final Mode mode;
    private final String user;
    private final int uid;
    private final int gid;
    private final boolean root;
    private final Path unshare;
    private final Path setpriv;
    private final Path prlimit;
    private final Path setsid;

    private Sandbox(Mode mode, String user, int uid, int gid, boolean root) {
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
        return new Sandbox(Mode.NONE, null, -1, -1, isRoot());
    }

    Mode mode() {
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
    static Sandbox detect(String userName, Mode wanted, Consumer<String> log) {
        boolean isRoot = isRoot();
        String name = userName == null ? DEFAULT_USER : userName;
        Optional<int[]> ids = name.isEmpty() ? Optional.empty() : lookup(name);
        Mode want = wanted == null ? Mode.AUTO : wanted;
        Sandbox s;
        if ((want == Mode.AUTO || want == Mode.NAMESPACE) && namespacesWork(isRoot)) {
            if (isRoot) {
                int[] id = ids.orElse(new int[] {65534, 65534});
                s = new Sandbox(Mode.NAMESPACE, ids.isPresent() ? name : "nobody", id[0], id[1], true);
            } else {
                s = new Sandbox(Mode.NAMESPACE, null, -1, -1, false);
            }
        } else if ((want == Mode.AUTO || want == Mode.NAMESPACE || want == Mode.USER) && isRoot && ids.isPresent()
                && tool("setpriv") != null) {
            s = new Sandbox(Mode.USER, name, ids.get()[0], ids.get()[1], true);
        } else {
            s = none();
            if (isRoot && want != Mode.NONE) {
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
     */
    record Box(Path dir, Path run, List<String> classPath, String marker, Sandbox sandbox) {
        /** A path inside {@code cp/} or {@code run/} as the child sees it. */
        String inChild(Path hostPath) {
            return sandbox.mode == Mode.NAMESPACE ? "/box/" + dir.relativize(hostPath).toString().replace('\\', '/')
                    : hostPath.toString();
        }

        /** The command prefix that starts a program in this box. */
        List<String> wrapper() {
            return sandbox.wrapper(this);
        }
    }

    /**
     * Makes a box under {@code parent}: {@code cp/<i>} for each class path entry (directories
     * copied, files linked when the child cannot write them, else copied; {@code filter} chooses
     * which files of a directory entry to take), and {@code run/}.
     */
    Box box(Path parent, List<Path> classPath, java.util.function.BiPredicate<Path, String> filter) throws IOException {
        Path dir = Files.createTempDirectory(parent, "box");
        Path cp = Files.createDirectories(dir.resolve("cp"));
        Path run = Files.createDirectories(dir.resolve("run"));
        Files.createDirectories(run.resolve("tmp"));
        Files.createDirectories(dir.resolveSibling(dir.getFileName() + "-root"));
        List<String> inside = new ArrayList<>();
        boolean link = mode != Mode.NONE;
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
            inside.add(mode == Mode.NAMESPACE ? "/box/cp/" + to.getFileName() : to.toString());
        }
        Box b = new Box(dir, run, inside, HexFormat.of().formatHex(random(12)), this);
        prepare(b);
        return b;
    }

    /** Permissions: the box readable by the child, run/ writable by it, nothing else. */
    private void prepare(Box b) throws IOException {
        try {
            if (mode == Mode.NONE) {
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
            if (user != null) {
                try (Stream<Path> s = Files.walk(b.run())) {
                    for (Path p : (Iterable<Path>) s::iterator) {
                        Files.setAttribute(p, "unix:uid", uid, java.nio.file.LinkOption.NOFOLLOW_LINKS);
                        Files.setAttribute(p, "unix:gid", gid, java.nio.file.LinkOption.NOFOLLOW_LINKS);
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

    private List<String> wrapper(Box b) {
        List<String> cmd = new ArrayList<>();
        if (prlimit != null) {
            cmd.addAll(List.of(prlimit.toString(), "--fsize=" + MAX_FILE_BYTES, "--core=0"));
            int nproc = processLimit();
            if (nproc > 0) {
                cmd.add("--nproc=" + nproc);
            }
            cmd.add("--");
        }
        if (mode == Mode.NAMESPACE) {
            cmd.add(unshare.toString());
            if (!root) {
                cmd.addAll(List.of("--user", "--map-root-user"));
            }
            cmd.addAll(List.of("--net", "--mount", "--pid", "--ipc", "--uts", "--fork", "--kill-child", "--", "sh", "-c",
                    NS_SCRIPT, "raylab-sandbox", b.dir().resolveSibling(b.dir().getFileName() + "-root").toString(),
                    b.dir().toString(), javaHome()));
            cmd.add(setpriv.toString());
            if (user != null) {
                cmd.addAll(List.of("--reuid=" + uid, "--regid=" + gid, "--clear-groups"));
            }
            cmd.addAll(List.of("--bounding-set=-all", "--inh-caps=-all", "--no-new-privs", "--",
                    "/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "HOME=/box/run", "TMPDIR=/tmp", "LANG=C.UTF-8",
                    "LD_LIBRARY_PATH=" + javaHome() + "/lib", "RAYLAB_BOX=" + b.marker()));
            return cmd;
        }
        if (setsid != null) {
            cmd.add(setsid.toString());
        }
        if (mode == Mode.USER) {
            cmd.addAll(List.of(setpriv.toString(), "--reuid=" + uid, "--regid=" + gid, "--clear-groups",
                    "--no-new-privs", "--"));
        }
        cmd.addAll(List.of("/usr/bin/env", "-i", "PATH=/usr/bin:/bin", "HOME=" + b.run(), "TMPDIR=" + b.run().resolve("tmp"),
                "LANG=C.UTF-8", "RAYLAB_BOX=" + b.marker()));
        return cmd;
    }

    /** RLIMIT_NPROC counts every process of the real user: the child's share on top of what runs now. */
    private int processLimit() {
        int childUid = user != null ? uid : root ? 0 : currentUid();
        if (childUid == 0 || childUid < 0) {
            return 0; // root is exempt from RLIMIT_NPROC
        }
        return countThreadsOf(childUid) + 512;
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
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            try {
                p.waitFor(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        for (int round = 0; round < 3; round++) {
            List<ProcessHandle> left = leftovers(b);
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
        GraderSetup.deleteTree(b.dir());
        GraderSetup.deleteTree(b.dir().resolveSibling(b.dir().getFileName() + "-root"));
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
                    boolean mine = new String(Files.readAllBytes(p.resolve("environ")), StandardCharsets.ISO_8859_1)
                            .contains(marker);
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
