package raylab.course;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;

/** Reads the milestones under {@code assignments/}, in course order. */
public final class Assignments {
    private static final ObjectMapper JSON = new ObjectMapper()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES);

    private final Path root;
    private final List<Assignment> all;

    private Assignments(Path root, List<Assignment> all) {
        this.root = root;
        this.all = List.copyOf(all);
    }

    /**
     * Loads every {@code assignments/*}{@code /assignment.json} under the project root.
     *
     * @throws IOException with a one-line message naming the file for a malformed description
     */
    public static Assignments load(Path projectRoot) throws IOException {
        Path dir = projectRoot.resolve("assignments");
        if (!Files.isDirectory(dir)) {
            throw new IOException(dir + ": no assignments folder (run from the project root)");
        }
        List<Assignment> out = new ArrayList<>();
        try (Stream<Path> folders = Files.list(dir)) {
            for (Path f : folders.sorted().toList()) {
                Path file = f.resolve("assignment.json");
                if (!Files.isRegularFile(file)) {
                    continue;
                }
                try {
                    Assignment a = JSON.readValue(file.toFile(), Assignment.class);
                    out.add(a.inFolder(projectRoot.relativize(f)));
                } catch (JsonProcessingException e) {
                    String where = e.getLocation() == null ? "" : ":" + e.getLocation().getLineNr()
                            + ":" + e.getLocation().getColumnNr();
                    throw new IOException(file + where + ": " + e.getOriginalMessage().split("\n")[0]);
                }
            }
        }
        out.sort(Comparator.comparingInt(Assignment::order));
        checkConsistent(projectRoot, out);
        return new Assignments(projectRoot, out);
    }

    /** The points of a milestone's data-driven cases (each case's "points", default 1). */
    public static double casePoints(Path projectRoot, Assignment a) throws IOException {
        double sum = 0;
        for (String rel : a.cases()) {
            Path f = projectRoot.resolve(a.folder()).resolve(rel);
            if (!Files.isRegularFile(f)) {
                throw new IOException(a.folder() + "/assignment.json: case file " + rel + " does not exist");
            }
            com.fasterxml.jackson.databind.JsonNode n;
            try {
                n = JSON.readTree(f.toFile());
            } catch (JsonProcessingException e) {
                throw new IOException(f + ": not valid JSON: " + e.getOriginalMessage().split("\n")[0]);
            }
            for (com.fasterxml.jackson.databind.JsonNode c : n.isArray() ? n : List.of(n)) {
                sum += c.path("points").asDouble(1);
            }
        }
        return sum;
    }

    private static void checkConsistent(Path projectRoot, List<Assignment> list) throws IOException {
        List<String> ids = list.stream().map(Assignment::id).toList();
        Map<String, String> ownerOfFile = new java.util.HashMap<>();
        for (Assignment a : list) {
            for (Assignment.StudentFile f : a.files()) {
                String other = ownerOfFile.putIfAbsent(f.path(), a.id());
                if (other != null && !other.equals(a.id())) {
                    throw new IOException(a.folder() + "/assignment.json: " + f.path() + " is a file of milestone "
                            + other + " already; a file belongs to one milestone: put the methods of " + a.id()
                            + " in a file of their own (docs/instructors.md, \"Splitting a topic over milestones\")");
                }
            }
        }
        for (Assignment a : list) {
            if (ids.indexOf(a.id()) != ids.lastIndexOf(a.id())) {
                throw new IOException("two assignments have the id '" + a.id() + "'");
            }
            double sum = a.tests().visiblePoints() + a.tests().hiddenPoints()
                    + a.scenes().stream().mapToInt(Assignment.GradedScene::points).sum()
                    + casePoints(projectRoot, a);
            if (Math.abs(sum - a.points()) > 1e-9) {
                throw new IOException(a.folder() + "/assignment.json: points is " + a.points()
                        + " but visiblePoints + hiddenPoints + scene points + case points add up to " + sum);
            }
            java.util.Set<String> hiddenClasses = new java.util.HashSet<>();
            for (String h : a.tests().hidden()) {
                hiddenClasses.add(Path.of(h).getFileName().toString().replaceFirst("\\.java$", ""));
            }
            for (java.util.Map.Entry<String, Double> w : a.tests().hiddenWeights().entrySet()) {
                String cls = w.getKey().contains(".") ? w.getKey().substring(0, w.getKey().indexOf('.')) : w.getKey();
                if (!hiddenClasses.contains(cls)) {
                    throw new IOException(a.folder() + "/assignment.json: tests.hiddenWeights names \"" + w.getKey()
                            + "\", which is not a class of tests.hidden (write Class or Class.method, simple names)");
                }
                if (w.getValue() == null || !(w.getValue() > 0) || w.getValue().isInfinite()) {
                    throw new IOException(a.folder() + "/assignment.json: tests.hiddenWeights." + w.getKey()
                            + " must be a number > 0, got " + w.getValue());
                }
            }
            for (String r : a.requires()) {
                if (!ids.contains(r)) {
                    throw new IOException(a.folder() + "/assignment.json: requires unknown milestone '" + r + "'");
                }
            }
        }
    }

    /** The project root the assignments were read from. */
    public Path root() {
        return root;
    }

    /** All milestones in course order. */
    public List<Assignment> all() {
        return all;
    }

    /** The milestone with this id. */
    public Optional<Assignment> byId(String id) {
        return all.stream().filter(a -> a.id().equals(id)).findFirst();
    }

    /** Milestone ids in course order. */
    public List<String> ids() {
        return all.stream().map(Assignment::id).toList();
    }

    /** The milestone a student-edited file belongs to, if any. */
    public Optional<Assignment> ownerOf(String relativePath) {
        String p = relativePath.replace('\\', '/');
        return all.stream().filter(a -> a.files().stream().anyMatch(f -> f.path().equals(p))).findFirst();
    }
}
