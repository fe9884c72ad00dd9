package raylab.grade;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;

/**
 * Data-driven unit cases: JSON files listed in an assignment's {@code "cases"} become graded
 * tests without Java. Each file holds one case object or an array of them (format in
 * grader/README.md). The grader generates one JUnit test class per milestone whose test methods
 * call {@code raylab.cases.CaseCheck.check(json)} (grader/tests), so cases run in the child JVM
 * through the same fail-closed protocol as every other test.
 */
public final class DataCases {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Set<String> VISIBILITIES = Set.of("visible", "hidden", "after_due_date", "after_published");

    /** One case: its name, points, visibility, the generated test method and the JSON text. */
    public record Case(String milestone, String name, double points, String visibility, String method,
            String json, String file) {
    }

    private DataCases() {
    }

    /** The generated test class of a milestone. */
    public static String className(String milestone) {
        StringBuilder b = new StringBuilder();
        for (String part : milestone.split("[^A-Za-z0-9]+")) {
            if (!part.isEmpty()) {
                b.append(Character.toUpperCase(part.charAt(0))).append(part.substring(1));
            }
        }
        return "raylab.cases." + b + "CasesTest";
    }

    /**
     * The generated test class of a milestone's visible cases: they run in the visible tests' JVM,
     * which never holds hidden data, so their messages can be shown at once.
     */
    public static String visibleClassName(String milestone) {
        return className(milestone).replace("CasesTest", "VisibleCasesTest");
    }

    /** Whether a case is shown at once. */
    public static boolean visible(Case c) {
        return "visible".equals(c.visibility());
    }

    /** Reads and checks a milestone's case files; a malformed file is an IOException naming it. */
    public static List<Case> load(Path root, Assignment a) throws IOException {
        List<Case> out = new ArrayList<>();
        for (raylab.course.GradingPlan.CaseFile file : raylab.course.GradingPlan.caseFiles(root, a)) {
            Path f = file.file();
            String rel = file.rel();
            for (JsonNode c : file.cases()) {
                String where = f + " case '" + c.path("name").asText("?") + "'";
                check(c, where);
                String method = String.format(Locale.ROOT, "case%02d_%s", out.size() + 1,
                        c.get("name").asText().replaceAll("[^A-Za-z0-9]+", "_"));
                out.add(new Case(a.id(), c.get("name").asText(), c.path("points").asDouble(1),
                        c.path("visibility").asText(a.tests().hiddenVisibility()), method, JSON.writeValueAsString(c),
                        a.folder() + "/" + rel));
            }
        }
        return out;
    }

    /** The sum of a milestone's case points. */
    public static double points(List<Case> cases) {
        return cases.stream().mapToDouble(Case::points).sum();
    }

    private static void check(JsonNode c, String where) throws IOException {
        if (!c.isObject()) {
            throw new IOException(where + ": a case must be a JSON object");
        }
        if (!c.hasNonNull("name") || c.get("name").asText().isBlank()) {
            throw new IOException(where + ": \"name\" is missing");
        }
        if (c.has("points") && !(c.get("points").isNumber() && c.get("points").asDouble() >= 0)) {
            throw new IOException(where + ": \"points\" must be a number ≥ 0");
        }
        if (c.has("visibility") && !VISIBILITIES.contains(c.get("visibility").asText())) {
            throw new IOException(where + ": \"visibility\" must be one of " + VISIBILITIES);
        }
        JsonNode s = c.get("surface");
        raylab.scene.SurfaceType type = s == null ? null : raylab.scene.SurfaceTypes.all().get(s.path("type").asText());
        if (type == null || !type.inDataCases()) {
            java.util.List<String> types = new java.util.ArrayList<>();
            raylab.scene.SurfaceTypes.all().values().stream().filter(raylab.scene.SurfaceType::inDataCases)
                    .forEach(t -> types.add(t.type()));
            throw new IOException(where + ": \"surface\" needs a \"type\" of " + types);
        }
        String problem = type.caseProblem(s);
        if (problem != null) {
            throw new IOException(where + ": " + problem);
        }
        JsonNode r = c.get("ray");
        if (r == null) {
            throw new IOException(where + ": \"ray\" is missing");
        }
        vec(r, "p", where);
        vec(r, "d", where);
        JsonNode e = c.get("expect");
        if (e == null || !e.has("hit") || !e.get("hit").isBoolean()) {
            throw new IOException(where + ": \"expect\" needs \"hit\": true or false");
        }
        if (e.get("hit").asBoolean()) {
            if (!e.has("t")) {
                throw new IOException(where + ": an expected hit needs \"t\"");
            }
            if (e.has("point")) {
                vec(e, "point", where);
            }
            if (e.has("normal")) {
                vec(e, "normal", where);
            }
        }
    }

    private static void vec(JsonNode parent, String field, String where) throws IOException {
        String problem = raylab.scene.types.CaseJson.vec3Problem(parent, field);
        if (problem != null) {
            throw new IOException(where + ": " + problem);
        }
    }

    /** Java source of the generated test class for a milestone's cases. */
    public static String testSource(String milestone, List<Case> cases) {
        return testSource(className(milestone), milestone, cases);
    }

    /** Java source of a generated test class {@code cls} holding {@code cases}. */
    public static String testSource(String cls, String milestone, List<Case> cases) {
        String simple = cls.substring(cls.lastIndexOf('.') + 1);
        StringBuilder b = new StringBuilder();
        b.append("package raylab.cases;\n\n// Generated by the raylab grader from the cases of milestone ").append(milestone)
                .append(".\n@org.junit.jupiter.api.Tag(\"").append(milestone).append("\")\nclass ").append(simple)
                .append(" {\n");
        for (Case c : cases) {
            b.append("    @org.junit.jupiter.api.Test\n    @org.junit.jupiter.api.DisplayName(\"")
                    .append(raylab.course.GradingPlan.javaString(c.name())).append("\")\n    void ").append(c.method())
                    .append("() throws Exception {\n        CaseCheck.check(\"").append(raylab.course.GradingPlan.javaString(c.json()))
                    .append("\");\n    }\n\n");
        }
        b.append("}\n");
        return b.toString();
    }
}
