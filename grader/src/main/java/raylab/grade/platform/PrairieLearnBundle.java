package raylab.grade.platform;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;

/**
 * {@code raylab bundle prairielearn --out DIR}: a folder laid out like a PrairieLearn course
 * repository, to copy into one.
 * <pre>
 * DIR/serverFilesCourse/raylab/grade.sh        the external-grading entrypoint
 * DIR/serverFilesCourse/raylab/raylab.jar      the grader
 * DIR/serverFilesCourse/raylab/due.txt         the due date (only with --due)
 * DIR/serverFilesCourse/raylab/assignments/... what grading reads: assignments, grader/tests (hidden
 *                                              tests), scenes with references, visible tests, helpers
 * DIR/questions/raylab/MILESTONE/info.json     one question per milestone (or raylab/all/ for the whole)
 * DIR/questions/raylab/MILESTONE/question.html a file upload for exactly the milestone's files
 * DIR/README.md
 * </pre>
 * PrairieLearn copies {@code serverFilesCourse/raylab/} into the grading container at
 * {@code /grade/serverFilesCourse/raylab/}; browsers never get serverFilesCourse (only the
 * clientFiles folders are served), so the hidden tests and the reference reach only the container,
 * where the grader's sandbox keeps them from the student's code.
 */
public final class PrairieLearnBundle {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private PrairieLearnBundle() {
    }

    /** The entrypoint: grades /grade/student (RAYLAB_GRADE_ROOT instead of /grade, for tests) into results.json. */
    static final String GRADE_SH = """
            #!/usr/bin/env bash
            # PrairieLearn external-grading entrypoint (written by raylab bundle prairielearn).
            #   grade.sh [MILESTONE]   grades /grade/student; writes /grade/results/results.json
            # Without MILESTONE every milestone is graded. For tests: RAYLAB_GRADE_ROOT replaces /grade,
            # RAYLAB_SANDBOX forces a sandbox mode (grade --sandbox).
            G="${RAYLAB_GRADE_ROOT:-/grade}"
            SRC="$G/serverFilesCourse/raylab"
            mkdir -p "$G/results"
            results="$G/results/results.json"
            rm -f "$results"
            # The unprivileged user that runs student code (the grader switches to it when root).
            if [ "$(id -u)" = 0 ] && ! id raylab-student >/dev/null 2>&1; then
              useradd -M -s /usr/sbin/nologin raylab-student >/dev/null 2>&1 || true
            fi
            # Student code must not read the grader, the hidden tests or the reference images.
            # PrairieLearn copies serverFilesCourse/raylab to $G/serverFilesCourse/raylab and again to
            # $G/shared/raylab, and its grader host extracts the job's tarball as root, which leaves $G
            # 0755 (grader/README.md, "PrairieLearn's /grade"): drop the copy, lock $G and all in it.
            rm -rf "$G/shared/raylab" 2>/dev/null || true
            chmod 700 "$G" "$G"/* "$G"/.[!.]* "$SRC" 2>/dev/null || true
            args=()
            if [ -n "${RAYLAB_SANDBOX:-}" ]; then args+=(--sandbox "$RAYLAB_SANDBOX"); fi
            if [ -n "${1:-}" ]; then args+=(--milestone "$1"); fi
            if [ -f "$SRC/due.txt" ]; then
              due="$(cat "$SRC/due.txt")"
              if [ "$(date -u +%s)" -ge "$(date -u -d "$due" +%s 2>/dev/null || echo 99999999999)" ]; then
                args+=(--after-due-date)
              fi
            fi
            cache="${RAYLAB_CACHE:-/tmp/raylab-cache}"
            mkdir -p "$cache" && chmod 755 "$cache"
            out="$(mktemp -d /tmp/raylab-out.XXXXXX)"
            (cd "$SRC" && java JVM_OPTIONS -jar raylab.jar grade "$G/student" --out "$out" --root "$SRC" --cache "$cache" \\
                --quiet --prairielearn "$results" "${args[@]}")
            if [ ! -s "$results" ]; then
              echo '{"gradable": false, "score": 0, "message": "The autograder could not run. You were not charged an attempt; please tell the course staff.", "tests": []}' \\
                > "$results"
            fi
            exit 0
            """.replace("JVM_OPTIONS", raylab.grade.JvmOptions.graderLine());

    public static void write(Path root, Assignments all, Path jar, List<Path> files, Path out, boolean whole, Instant due,
            String image, int timeout) throws IOException {
        Path target = out.toAbsolutePath().normalize();
        if (Files.exists(target)) {
            throw UserError.badInput(out + " already exists: give a new folder");
        }
        Path parent = target.getParent();
        Files.createDirectories(parent);
        Path tmp = Files.createTempDirectory(parent, "." + target.getFileName() + ".");
        try {
            Path src = Files.createDirectories(tmp.resolve("serverFilesCourse/raylab"));
            write(src.resolve("grade.sh"), GRADE_SH);
            src.resolve("grade.sh").toFile().setExecutable(true, false);
            Files.copy(jar, src.resolve("raylab.jar"));
            if (due != null) {
                write(src.resolve("due.txt"), due.toString() + "\n");
            }
            for (Path f : files) {
                Path t = src.resolve(root.relativize(f).toString());
                Files.createDirectories(t.getParent());
                Files.copy(f, t);
            }
            List<Assignment> questions = whole ? List.of() : all.all();
            if (whole) {
                question(tmp, "all", "raylab: the whole ray tracer", all.all(), null, image, timeout, due != null);
            } else {
                for (Assignment a : questions) {
                    question(tmp, a.id(), "raylab " + a.id() + ": " + a.title(), List.of(a), a.id(), image, timeout, due != null);
                }
            }
            write(tmp.resolve("README.md"), readme(whole, due, timeout));
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            if (Files.exists(tmp)) {
                JavaBuild.deleteTree(tmp);
            }
        }
    }

    private static void question(Path dir, String id, String title, List<Assignment> milestones, String milestone,
            String image, int timeout, boolean due) throws IOException {
        Path q = Files.createDirectories(dir.resolve("questions/raylab").resolve(id));
        Map<String, Object> info = new LinkedHashMap<>();
        info.put("uuid", UUID.nameUUIDFromBytes(("raylab/" + id).getBytes(StandardCharsets.UTF_8)).toString());
        info.put("title", title);
        info.put("topic", "raylab");
        info.put("tags", milestone == null ? List.of("raylab") : List.of("raylab", milestone));
        info.put("type", "v3");
        info.put("singleVariant", true);
        info.put("gradingMethod", "External");
        Map<String, Object> ext = new LinkedHashMap<>();
        ext.put("enabled", true);
        ext.put("image", image);
        ext.put("serverFilesCourse", List.of("raylab/"));
        ext.put("entrypoint", "/grade/serverFilesCourse/raylab/grade.sh" + (milestone == null ? "" : " " + milestone));
        ext.put("timeout", timeout);
        ext.put("enableNetworking", false);
        info.put("externalGradingOptions", ext);
        write(q.resolve("info.json"), JSON.writeValueAsString(info) + "\n");
        List<String> names = new ArrayList<>();
        int points = 0;
        for (Assignment a : milestones) {
            points += a.points();
            for (Assignment.StudentFile f : a.files()) {
                names.add(f.path().substring(f.path().lastIndexOf('/') + 1));
            }
        }
        StringBuilder html = new StringBuilder();
        html.append("<pl-question-panel>\n  <p>").append(esc(title)).append(" (").append(points).append(" points).</p>\n");
        html.append("  <p>Upload ").append(names.size() == 1 ? "your file " : "your files ");
        for (int i = 0; i < names.size(); i++) {
            html.append(i == 0 ? "" : i == names.size() - 1 ? " and " : ", ").append("<code>").append(esc(names.get(i)))
                    .append("</code>");
        }
        html.append(" from <code>src/main/java/</code> of your starter. Run <code>./raylab check")
                .append(milestone == null ? "" : " " + esc(milestone))
                .append("</code> first: it runs the visible tests and scenes the grader runs.</p>\n");
        html.append("  <p>Your score includes the hidden tests and data cases, graded at every submission: they are"
                + " shown as one row with their total; which ones passed and their messages stay withheld"
                + (due ? " until the due date" : "") + ".</p>\n</pl-question-panel>\n\n");
        html.append("<pl-file-upload file-names=\"").append(esc(String.join(", ", names))).append("\"></pl-file-upload>\n\n");
        html.append("<pl-submission-panel>\n  <pl-external-grader-results></pl-external-grader-results>\n"
                + "  <pl-file-preview></pl-file-preview>\n</pl-submission-panel>\n");
        write(q.resolve("question.html"), html.toString());
    }

    private static String readme(boolean whole, Instant due, int timeout) {
        return """
                # raylab for PrairieLearn (written by `raylab bundle prairielearn`)

                Copy `serverFilesCourse/raylab/` into the course repository's `serverFilesCourse/`, and
                `questions/raylab/` into its `questions/`; then add the questions to an assessment.

                - %s
                - Grading image `prairielearn/grader-java` (a JDK); time limit %d s; no network.
                - Each grading builds the grader's cache in the container's /tmp first (the container starts empty).
                - %s
                - Details: docs/instructors.md, "PrairieLearn", in the raylab project.
                """.formatted(whole ? "One question, `raylab/all`, grades every milestone."
                        : "One question per milestone (`raylab/sphere`, ...), each grading only its milestone.",
                        timeout, due == null ? "No due date given: every grading counts the hidden tests and data cases in"
                                + " the score; students see them as one row per milestone with their total, never their names"
                                + " or messages (bundle again with `--due` to show them in full after a due date)."
                                : "Due " + due + ": every grading counts the hidden tests and data cases; before the due date"
                                + " students see their total only, gradings after it show each with its message.");
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    private static void write(Path p, String text) throws IOException {
        Files.writeString(p, text, StandardCharsets.UTF_8);
    }
}
