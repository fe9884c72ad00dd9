package raylab.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.nio.file.attribute.UserPrincipal;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Runs student code as an unprivileged user when the grader runs as root (as on Gradescope):
 * child JVMs are started through {@code setpriv} with that user's uid and gid, only their own
 * working directory is writable to them, and after each milestone every process of that user is
 * killed. Not root, or no such user: children run as the grader's own user (logged).
 */
final class Sandbox {
    /** The default name of the unprivileged user (created by the bundle's setup.sh). */
    static final String DEFAULT_USER = "raylab-student";

    private final String user;
    private final int uid;
    private final int gid;

    private Sandbox(String user, int uid, int gid) {
        this.user = user;
        this.uid = uid;
        this.gid = gid;
    }

    /** No sandbox: children run as this process's user. */
    static Sandbox none() {
        return new Sandbox(null, -1, -1);
    }

    boolean active() {
        return user != null;
    }

    String user() {
        return user;
    }

    /**
     * The sandbox for this process: active when running as root and the user exists and
     * {@code setpriv} is available. {@code log} receives one line saying which mode is used.
     */
    static Sandbox detect(String userName, java.util.function.Consumer<String> log) {
        if (userName != null && userName.isEmpty()) {
            log.accept("sandbox: off (--sandbox-user \"\"): student code runs as " + System.getProperty("user.name"));
            return none();
        }
        String name = userName == null ? DEFAULT_USER : userName;
        if (!"root".equals(System.getProperty("user.name")) && !isRoot()) {
            log.accept("sandbox: not running as root, so student code runs as " + System.getProperty("user.name")
                    + " (on Gradescope the grader runs as root and uses the user " + DEFAULT_USER + ")");
            return none();
        }
        Optional<int[]> ids = lookup(name);
        Path setpriv = Stream.of("/usr/bin/setpriv", "/bin/setpriv", "/usr/sbin/setpriv").map(Path::of)
                .filter(Files::isExecutable).findFirst().orElse(null);
        if (ids.isEmpty() || setpriv == null) {
            log.accept("sandbox: running as root but " + (ids.isEmpty() ? "there is no user '" + name
                    + "' (create it: useradd -M -s /usr/sbin/nologin " + name + ")" : "setpriv is missing")
                    + ": student code runs as root");
            return none();
        }
        log.accept("sandbox: student code runs as user " + name + " (uid " + ids.get()[0] + ")");
        return new Sandbox(name, ids.get()[0], ids.get()[1]);
    }

    private static boolean isRoot() {
        try {
            Object uid = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
            return Integer.valueOf(0).equals(uid);
        } catch (Exception e) {
            return false;
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
            // no passwd file: no sandbox
        }
        return Optional.empty();
    }

    /** The command prefix for a child JVM (empty when not active). */
    List<String> wrapper() {
        if (!active()) {
            return List.of();
        }
        return List.of("setpriv", "--reuid=" + uid, "--regid=" + gid, "--clear-groups", "--");
    }

    /** A directory the child may write to: owned by the sandbox user. */
    void giveTo(Path dir) throws IOException {
        if (!active()) {
            return;
        }
        UserPrincipal owner = dir.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName(user);
        Files.setOwner(dir, owner);
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
    }

    /** Makes a grader directory tree readable (not writable) by the child. */
    static void readableByAll(Path root) throws IOException {
        try (Stream<Path> s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (Files.isSymbolicLink(p)) {
                    continue;
                }
                Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(
                        Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
            }
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system
        }
    }

    /** Kills every process of the sandbox user (what the milestone's children left behind). */
    void killAll() {
        if (!active()) {
            return;
        }
        ProcessHandle.allProcesses()
                .filter(ph -> ph.info().user().map(user::equals).orElse(false))
                .forEach(ProcessHandle::destroyForcibly);
    }
}
