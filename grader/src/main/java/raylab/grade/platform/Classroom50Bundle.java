package raylab.grade.platform;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;

/**
 * {@code raylab bundle classroom50 --out DIR}: the files for the teacher's {@code classroom50}
 * repository.
 * <pre>
 * DIR/autograders/ASSIGNMENT/autograder.py  runs ./raylab check in the student's checkout, writes result.json
 * DIR/assignment.json                       runtime, release_assets and submission_tags for the assignment
 * DIR/README.md
 * </pre>
 * Classroom 50 publishes autograders through GitHub Pages and runs them in the student's own
 * repository on GitHub Actions, in the same job as the student's code: whatever the autograder
 * holds, a student can read. So this autograder holds nothing of the grader: it runs the
 * starter's own {@code ./raylab check} (visible tests, visible data cases, scenes against the
 * reference images the starter already has) as feedback. The grade of record, hidden tests
 * included, comes from {@code raylab grade-all} on a machine of the course staff.
 */
public final class Classroom50Bundle {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private Classroom50Bundle() {
    }

    static final String AUTOGRADER = """
            \"\"\"raylab feedback for Classroom 50 (written by `raylab bundle classroom50`).

            Runs in the student's checkout: `./raylab check MILESTONE --classroom50 result.json` runs the
            milestone's visible tests, visible data cases and scenes (the same ones the student runs) and
            writes result.json (schema classroom50/result/v1). The milestone is the milestone tag at the
            graded commit (git tag sphere && git push origin sphere), else RAYLAB_MILESTONE, else all.
            Nothing hidden is here: Classroom 50 publishes this file on GitHub Pages.
            \"\"\"

            import json, os, subprocess, sys
            from pathlib import Path

            MILESTONES = @MILESTONES@


            def milestone():
                if os.environ.get("RAYLAB_MILESTONE"):
                    return os.environ["RAYLAB_MILESTONE"]
                try:
                    tags = subprocess.run(["git", "tag", "--points-at", "HEAD"], capture_output=True, text=True,
                                          check=False).stdout.split()
                except OSError:
                    tags = []
                # The latest milestone tagged at this commit (sphere, box, ...: course order).
                found = [m for m in MILESTONES if m in tags]
                return found[-1] if found else None


            def main():
                result = Path("result.json")
                if result.exists():
                    result.unlink()
                m = milestone()
                cmd = ["bash", "./raylab", "check"] + ([m] if m else []) + ["--classroom50", str(result)]
                print("raylab:", " ".join(cmd), flush=True)
                proc = subprocess.run(cmd, check=False)
                # Exit status 1 is a failed test or a differing scene: graded. Anything else, no file or a
                # file that is not JSON: the grading failed. Classroom 50's runner turns a non-zero exit of
                # autograder.py into an error result (status=error, no score), its way to say so.
                data = None
                if proc.returncode in (0, 1) and result.is_file():
                    try:
                        data = json.loads(result.read_text())
                    except ValueError:
                        data = None
                if data is None:
                    print("::error::raylab: the autograder failed (raylab check exit status %d, no valid result.json): "
                          "no points were decided. This is a problem of the course's autograder, not of your code: "
                          "please tell the course staff." % proc.returncode, file=sys.stderr)
                    sys.exit(1)
                print("raylab: %d / %d (hundredths of a point, visible parts)" % (data["score"], data["max-score"]))


            if __name__ == "__main__":
                main()
            """;

    public static void write(Assignments all, String assignment, String java, Path out) throws IOException {
        if (!assignment.matches("[a-z0-9][a-z0-9-]*")) {
            throw UserError.badInput("--assignment: a slug of lower-case letters, digits and '-', got '" + assignment + "'");
        }
        Path target = out.toAbsolutePath().normalize();
        if (Files.exists(target)) {
            throw UserError.badInput(out + " already exists: give a new folder");
        }
        Files.createDirectories(target.getParent());
        Path tmp = Files.createTempDirectory(target.getParent(), "." + target.getFileName() + ".");
        try {
            List<String> ids = all.ids();
            Path ag = Files.createDirectories(tmp.resolve("autograders").resolve(assignment));
            String list = "[" + String.join(", ", ids.stream().map(i -> "\"" + i + "\"").toList()) + "]";
            Files.writeString(ag.resolve("autograder.py"), AUTOGRADER.replace("@MILESTONES@", list), StandardCharsets.UTF_8);
            Files.writeString(tmp.resolve("assignment.json"), JSON.writeValueAsString(assignmentFields(all, java)) + "\n",
                    StandardCharsets.UTF_8);
            Files.writeString(tmp.resolve("README.md"), readme(assignment), StandardCharsets.UTF_8);
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            if (Files.exists(tmp)) {
                JavaBuild.deleteTree(tmp);
            }
        }
    }

    /** The assignment's runtime, release assets (each scene's render and difference) and milestone tags. */
    static Map<String, Object> assignmentFields(Assignments all, String java) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("runtime", Map.of("java", java));
        List<String> assets = new ArrayList<>();
        for (Assignment a : all.all()) {
            for (Assignment.GradedScene s : a.scenes()) {
                String name = s.scene().substring(s.scene().lastIndexOf('/') + 1).replaceFirst("\\.json$", "");
                assets.add("out/" + name + ".png");
                assets.add("out/" + name + ".diff.png");
            }
        }
        if (assets.size() > 50) {
            throw UserError.badInput(assets.size() + " release assets: Classroom 50 attaches at most 50");
        }
        m.put("release_assets", assets);
        m.put("submission_tags", all.ids());
        return m;
    }

    private static String readme(String assignment) {
        return """
                # raylab for Classroom 50 (written by `raylab bundle classroom50`)

                1. Copy `autograders/%1$s/` into `CLASSROOM/autograders/` of the organization's `classroom50`
                   repository (the assignment's slug must be `%1$s`, or bundle again with `--assignment`).
                2. Add the fields of `assignment.json` (`runtime`, `release_assets`, `submission_tags`) to the
                   assignment's entry in `CLASSROOM/assignments.json` (or set them in the web form).
                3. Students push a milestone tag (`git tag sphere && git push origin sphere`) or a `submit/*` tag.

                What is graded where: autograder.py runs `./raylab check` in the student's checkout — the
                visible tests, visible data cases and scenes, which the student can run too — and the Release
                shows that score (hundredths of a point) and the scene images. Classroom 50 publishes
                autograders on GitHub Pages and runs them beside the student's code, so nothing hidden is
                here. The grade of record, hidden tests included, is `raylab grade-all` run by the course
                staff over the students' repositories at their submission tags (docs/instructors.md).
                """.formatted(assignment);
    }
}
