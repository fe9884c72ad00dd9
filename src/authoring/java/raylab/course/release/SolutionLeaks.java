package raylab.course.release;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.spi.ToolProvider;
import java.util.stream.Stream;

import raylab.course.SolutionRegions;

/**
 * Whether a reference method body is anywhere in a starter, under any name. Two checks:
 * <ul>
 * <li><b>Bytecode.</b> The student files compiled with their solutions give the reference
 * methods: every method whose code differs from the same method compiled from the starter's stub
 * (or that the stub does not have: a solution's helper). Each is normalized ({@code javap -c -p}
 * with the instruction offsets, constant-pool indices and the class's own name taken out, so
 * line numbers, names of the method, its class and its local variables do not matter) and
 * compared with every method of every class of the compiled starter. Methods of fewer than
 * {@link #MIN_INSTRUCTIONS} instructions are too small to be a solution ({@code return true;}).</li>
 * <li><b>Source.</b> Each solution region as a token sequence (comments and layout dropped):
 * no run of {@link #WINDOW} tokens of it (the whole region when shorter, from
 * {@link #MIN_TOKENS} tokens on) may appear in any starter source.</li>
 * </ul>
 */
public final class SolutionLeaks {
    static final int MIN_INSTRUCTIONS = 10;
    static final int WINDOW = 40;
    static final int MIN_TOKENS = 16;

    private SolutionLeaks() {
    }

    /** One reference method (or region) found in the starter. */
    public record Leak(String kind, String solution, String foundIn) {
        @Override
        public String toString() {
            return kind + ": " + solution + " is in " + foundIn;
        }
    }

    /**
     * Both checks on a written starter: {@code root} is the instructor's tree, {@code starterMain}
     * the starter's compiled {@code src/main/java} (the stubs), {@code starterClasses} every folder
     * of compiled starter classes to search; {@code work} receives the solutions' build.
     */
    public static List<Leak> find(Path root, Path starter, raylab.course.Assignments assignments, Path starterMain,
            List<Path> starterClasses, List<Path> libraries, Path work) throws IOException {
        java.util.Set<String> all = new java.util.TreeSet<>(assignments.ids());
        Map<String, String> withSolutions = new LinkedHashMap<>();
        Map<String, String> instructor = new LinkedHashMap<>();
        for (raylab.course.Assignment a : assignments.all()) {
            for (raylab.course.Assignment.StudentFile f : a.files()) {
                Path file = root.resolve(f.path());
                withSolutions.put(f.path(), raylab.course.MilestoneBuild.withSolutions(file, f.path(), all));
                instructor.put(f.path(), Files.readString(file, StandardCharsets.UTF_8));
            }
        }
        List<Path> below = new ArrayList<>();
        below.add(starterMain);
        below.addAll(libraries);
        Path classes = work.resolve("classes");
        raylab.course.JavaBuild.Result r = raylab.course.MilestoneBuild.compileOverlay(withSolutions, work.resolve("src"),
                below, classes);
        if (!r.success()) {
            throw new IOException("the solutions do not compile over the starter: " + r.errors());
        }
        List<Leak> out = new ArrayList<>(inBytecode(classes, starterMain, starterClasses));
        out.addAll(inSources(instructor, starter));
        return out;
    }

    /**
     * Bytecode check: {@code solution} holds the student files' classes compiled with their
     * solutions, {@code stubs} the same classes from the starter (its compiled main tree will do),
     * {@code starter} every folder of compiled starter classes to search.
     */
    public static List<Leak> inBytecode(Path solution, Path stubs, List<Path> starter) throws IOException {
        Map<String, String> stubMethods = new HashMap<>();
        Map<String, String> reference = new LinkedHashMap<>();
        for (Path cls : classFiles(solution)) {
            String rel = solution.relativize(cls).toString();
            Map<String, String> sol = methods(cls);
            Path stub = stubs.resolve(rel);
            Map<String, String> st = Files.isRegularFile(stub) ? methods(stub) : Map.of();
            stubMethods.putAll(st);
            for (Map.Entry<String, String> m : sol.entrySet()) {
                if (!m.getValue().equals(st.get(m.getKey())) && instructions(m.getValue()) >= MIN_INSTRUCTIONS) {
                    reference.put(m.getKey(), m.getValue());
                }
            }
        }
        Map<String, List<String>> byCode = new HashMap<>();
        reference.forEach((name, code) -> byCode.computeIfAbsent(code, k -> new ArrayList<>()).add(name));
        List<Leak> out = new ArrayList<>();
        for (Path dir : starter) {
            for (Path cls : classFiles(dir)) {
                for (Map.Entry<String, String> m : methods(cls).entrySet()) {
                    List<String> hit = byCode.get(m.getValue());
                    if (hit != null) {
                        for (String h : hit) {
                            out.add(new Leak("bytecode", h, m.getKey()));
                        }
                    }
                }
            }
        }
        return out;
    }

    /**
     * Source check: the solution regions of {@code studentFiles} (instructor's text, by path
     * relative to the project) against every {@code .java} file under {@code starter}.
     */
    public static List<Leak> inSources(Map<String, String> studentFiles, Path starter) throws IOException {
        List<Path> sources;
        try (Stream<Path> s = Files.walk(starter)) {
            sources = s.filter(p -> p.toString().endsWith(".java") && Files.isRegularFile(p)).sorted().toList();
        }
        Map<Path, String> starterTokens = new LinkedHashMap<>();
        for (Path p : sources) {
            starterTokens.put(p, " " + String.join(" ", tokens(Files.readString(p, StandardCharsets.UTF_8))) + " ");
        }
        List<Leak> out = new ArrayList<>();
        for (Map.Entry<String, String> f : studentFiles.entrySet()) {
            for (SolutionRegions.Region r : SolutionRegions.parse(f.getKey(), f.getValue())) {
                List<String> t = tokens(String.join("\n", r.solution()));
                if (t.size() < MIN_TOKENS) {
                    continue;
                }
                String where = f.getKey() + ":" + r.beginLine() + " (solution region " + r.milestone() + ")";
                int w = Math.min(WINDOW, t.size());
                search: for (Map.Entry<Path, String> s : starterTokens.entrySet()) {
                    for (int i = 0; i + w <= t.size(); i++) {
                        String window = " " + String.join(" ", t.subList(i, i + w)) + " ";
                        if (s.getValue().contains(window)) {
                            out.add(new Leak("source", where, starter.relativize(s.getKey()) + " (from the token "
                                    + (i + 1) + " of the region: " + abbreviate(String.join(" ", t.subList(i, i + w))) + ")"));
                            break search;
                        }
                    }
                }
            }
        }
        return out;
    }

    private static String abbreviate(String s) {
        return s.length() <= 80 ? s : s.substring(0, 77) + "...";
    }

    /** Java tokens without comments and whitespace (strings and characters kept whole). */
    static List<String> tokens(String src) {
        List<String> out = new ArrayList<>();
        int i = 0;
        int n = src.length();
        while (i < n) {
            char c = src.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (src.startsWith("//", i)) {
                int e = src.indexOf('\n', i);
                i = e < 0 ? n : e;
            } else if (src.startsWith("/*", i)) {
                int e = src.indexOf("*/", i + 2);
                i = e < 0 ? n : e + 2;
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < n && src.charAt(j) != c) {
                    j += src.charAt(j) == '\\' ? 2 : 1;
                }
                j = Math.min(n, j + 1);
                out.add(src.substring(i, j));
                i = j;
            } else if (Character.isJavaIdentifierStart(c) || Character.isDigit(c)) {
                int j = i + 1;
                while (j < n && (Character.isJavaIdentifierPart(src.charAt(j))
                        || (Character.isDigit(c) && (src.charAt(j) == '.' || ((src.charAt(j) == '-'
                                || src.charAt(j) == '+') && (src.charAt(j - 1) == 'e' || src.charAt(j - 1) == 'E')))))) {
                    j++;
                }
                out.add(src.substring(i, j));
                i = j;
            } else {
                out.add(String.valueOf(c));
                i++;
            }
        }
        return out;
    }

    private static List<Path> classFiles(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(p -> p.toString().endsWith(".class") && Files.isRegularFile(p)).sorted().toList();
        }
    }

    private static final Pattern OFFSET = Pattern.compile("^\\s*\\d+: ");
    private static final Pattern CONSTANT = Pattern.compile("#\\d+(:|,\\s*\\d+)?");

    /** A class file's methods: "Class.name(descriptor)" → normalized code (only methods with code). */
    static Map<String, String> methods(Path classFile) throws IOException {
        ToolProvider javap = ToolProvider.findFirst("javap")
                .orElseThrow(() -> new IOException("no javap in this runtime: run the release check with a JDK"));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = javap.run(new PrintWriter(out), new PrintWriter(err), "-c", "-p", classFile.toString());
        if (status != 0) {
            throw new IOException("javap " + classFile + ": " + err.toString().strip());
        }
        String className = null;
        Map<String, String> result = new LinkedHashMap<>();
        String method = null;
        StringBuilder code = null;
        for (String line : out.toString().split("\n")) {
            if (className == null) {
                var m = Pattern.compile("(?:class|interface|enum|record) ([\\w.$]+)").matcher(line);
                if (!line.startsWith(" ") && !line.startsWith("Compiled") && m.find()) {
                    className = m.group(1);
                }
                continue;
            }
            if (line.startsWith("  ") && !line.startsWith("   ") && line.endsWith(";")) {
                method = line.strip();
                code = null;
            } else if (line.strip().equals("Code:") && method != null) {
                code = new StringBuilder();
                result.put(className + ": " + method, "");
            } else if (code != null && line.startsWith("     ")) {
                String own = className.replace('.', '/');
                String norm = CONSTANT.matcher(OFFSET.matcher(line).replaceFirst("")).replaceAll("#")
                        .replace(own + ".", "THIS.").replace(own + ":", "THIS:").replace(own + "\"", "THIS\"")
                        .replaceAll("\\s+", " ").strip();
                code.append(norm).append('\n');
                result.put(className + ": " + method, code.toString());
            } else if (line.isBlank() || line.equals("}")) {
                code = null;
            }
        }
        return result;
    }

    private static int instructions(String code) {
        return (int) code.lines().filter(l -> !l.isBlank() && !l.startsWith("Exception") && !l.startsWith("from")).count();
    }
}
