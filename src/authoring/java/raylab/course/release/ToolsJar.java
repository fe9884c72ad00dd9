package raylab.course.release;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;

import raylab.course.SourceRoots;

/**
 * The tools module as the starter has it (docs/architecture.md): the classes compiled from
 * {@code src/tools/java} in a jar, their sources in a sources jar, and a pom, laid out as a Maven
 * repository in the starter's {@code lib/} folder, which the starter's pom.xml names. The version
 * names the jar's content ({@code 1.0.0-} and the first 12 hex digits of its SHA-256), so a new
 * release never meets an older jar of the same version in a student's Maven cache. The same
 * sources and classes give the same bytes on every run (sorted entries, one fixed time).
 */
final class ToolsJar {
    /** The group and artifact the starter's pom.xml depends on. */
    static final String GROUP = "org.raylab";
    static final String ARTIFACT = "raylab-tools";
    /** The starter's Maven repository folder. */
    static final String REPOSITORY = "lib";

    private static final LocalDateTime TIME = LocalDateTime.of(2026, 1, 1, 0, 0);

    /** A built jar: its version and the repository files (relative starter path to bytes). */
    record Built(String version, SortedMap<String, byte[]> files) {
        /** The tools jar's path in the starter. */
        String jar() {
            return folder(version) + ARTIFACT + "-" + version + ".jar";
        }
    }

    private ToolsJar() {
    }

    /**
     * Builds the jar from the tools' sources under {@code root} and their classes as this JVM
     * loaded them (target/classes, or target/raylab.jar).
     */
    static Built build(Path root) throws IOException {
        Set<String> tools = SourceRoots.classesUnder(root, SourceRoots.TOOLS);
        if (tools.isEmpty()) {
            throw new IOException(root.resolve(SourceRoots.TOOLS) + ": missing (the tools the starter gets as a jar)");
        }
        SortedMap<String, byte[]> classes = compiledClasses(tools);
        List<String> unbuilt = new ArrayList<>();
        for (String t : tools) {
            if (!classes.containsKey(t.replace('.', '/') + ".class")) {
                unbuilt.add(t);
            }
        }
        if (!unbuilt.isEmpty()) {
            throw new IOException("the tools are not built (" + unbuilt.get(0) + (unbuilt.size() > 1 ? " and "
                    + (unbuilt.size() - 1) + " more" : "") + " has no class): run ./mvnw -DskipTests package first");
        }
        SortedMap<String, byte[]> sources = new TreeMap<>();
        Path src = root.resolve(SourceRoots.TOOLS);
        try (Stream<Path> s = Files.walk(src)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (Files.isRegularFile(p)) {
                    sources.put(src.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
                }
            }
        }
        byte[] jar = jar(classes);
        String version = "1.0.0-" + HexFormat.of().formatHex(digest("SHA-256", jar)).substring(0, 12);
        String base = folder(version) + ARTIFACT + "-" + version;
        SortedMap<String, byte[]> files = new TreeMap<>();
        put(files, base + ".jar", jar);
        put(files, base + "-sources.jar", jar(sources));
        put(files, base + ".pom", pom(version).getBytes(StandardCharsets.UTF_8));
        return new Built(version, files);
    }

    private static String folder(String version) {
        return REPOSITORY + "/" + GROUP.replace('.', '/') + "/" + ARTIFACT + "/" + version + "/";
    }

    /** A file and its .sha1, which Maven checks when it copies the file into its cache. */
    private static void put(SortedMap<String, byte[]> files, String path, byte[] bytes) {
        files.put(path, bytes);
        files.put(path + ".sha1", HexFormat.of().formatHex(digest("SHA-1", bytes)).getBytes(StandardCharsets.US_ASCII));
    }

    /** The tools' pom: no dependencies of its own (the starter's pom.xml lists the libraries). */
    static String pom(String version) {
        return """
                <?xml version="1.0" encoding="UTF-8"?>
                <project xmlns="http://maven.apache.org/POM/4.0.0"
                         xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
                         xsi:schemaLocation="http://maven.apache.org/POM/4.0.0 https://maven.apache.org/xsd/maven-4.0.0.xsd">
                  <modelVersion>4.0.0</modelVersion>
                  <groupId>%s</groupId>
                  <artifactId>%s</artifactId>
                  <version>%s</version>
                  <packaging>jar</packaging>
                  <description>raylab's tools (the raylab command, check, the test JVM, inspect): built by raylab release.</description>
                </project>
                """.formatted(GROUP, ARTIFACT, version);
    }

    /** The class files compiled from {@code tools}, by entry name, from where this JVM loaded the tools. */
    private static SortedMap<String, byte[]> compiledClasses(Set<String> tools) throws IOException {
        Path where;
        try {
            where = Path.of(raylab.cli.Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException | RuntimeException e) {
            throw new IOException("cannot find where the tools' classes were loaded from: " + e.getMessage());
        }
        SortedMap<String, byte[]> out = new TreeMap<>();
        if (Files.isDirectory(where)) {
            try (Stream<Path> s = Files.walk(where)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    String name = where.relativize(p).toString().replace('\\', '/');
                    if (Files.isRegularFile(p) && SourceRoots.compiledFrom(name, tools)) {
                        out.put(name, Files.readAllBytes(p));
                    }
                }
            }
        } else {
            try (JarFile jar = new JarFile(where.toFile())) {
                for (JarEntry e : (Iterable<JarEntry>) jar.stream()::iterator) {
                    if (!e.isDirectory() && SourceRoots.compiledFrom(e.getName(), tools)) {
                        try (InputStream in = jar.getInputStream(e)) {
                            out.put(e.getName(), in.readAllBytes());
                        }
                    }
                }
            }
        }
        return out;
    }

    /** A jar of {@code entries} in their sorted order, every entry at one fixed time. */
    static byte[] jar(Map<String, byte[]> entries) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (JarOutputStream out = new JarOutputStream(bytes)) {
            ZipEntry manifest = new ZipEntry(JarFile.MANIFEST_NAME);
            manifest.setTimeLocal(TIME);
            out.putNextEntry(manifest);
            out.write("Manifest-Version: 1.0\r\nCreated-By: raylab release\r\n\r\n".getBytes(StandardCharsets.UTF_8));
            out.closeEntry();
            for (Map.Entry<String, byte[]> e : new TreeMap<>(entries).entrySet()) {
                ZipEntry z = new ZipEntry(e.getKey());
                z.setTimeLocal(TIME);
                out.putNextEntry(z);
                out.write(e.getValue());
                out.closeEntry();
            }
        }
        return bytes.toByteArray();
    }

    private static byte[] digest(String algorithm, byte[] bytes) {
        try {
            return MessageDigest.getInstance(algorithm).digest(bytes);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(algorithm + " is missing from this JDK", e);
        }
    }
}
