package raylab.course.release;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * The starter's README.md, from the template {@code assignments/STARTER-README.md}. The template
 * is Markdown with one placeholder, <code>{{MILESTONES}}</code>, replaced by a table of the
 * milestones (order, id, title, handout link, files to edit), in course order.
 */
final class StarterReadme {
    private static final Pattern PLACEHOLDER = Pattern.compile("\\{\\{([A-Z_]+)}}");

    private StarterReadme() {
    }

    static String render(Path root, String template, Assignments assignments) throws IOException {
        Path file = root.resolve(template);
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": missing (the template of the starter's README)");
        }
        String text = Files.readString(file, StandardCharsets.UTF_8);
        Matcher m = PLACEHOLDER.matcher(text);
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            if (!m.group(1).equals("MILESTONES")) {
                throw new IOException(template + ": unknown placeholder {{" + m.group(1) + "}} (only {{MILESTONES}})");
            }
            m.appendReplacement(sb, Matcher.quoteReplacement(milestoneTable(assignments)));
        }
        m.appendTail(sb);
        return sb.toString();
    }

    static String milestoneTable(Assignments assignments) {
        StringBuilder t = new StringBuilder();
        t.append("| # | Milestone | What you write | Handout | Files to edit | Needs |\n");
        t.append("|---|-----------|----------------|---------|---------------|-------|\n");
        for (Assignment a : assignments.all()) {
            String folder = a.folder().toString().replace('\\', '/');
            StringBuilder files = new StringBuilder();
            StringBuilder methods = new StringBuilder();
            for (Assignment.StudentFile f : a.files()) {
                files.append(files.length() == 0 ? "" : ", ").append('`').append(f.path()).append('`');
                for (String method : f.methods()) {
                    methods.append(methods.length() == 0 ? "" : ", ").append('`').append(method).append('`');
                }
            }
            t.append("| ").append(a.order()).append(" | `").append(a.id()).append("` ").append(a.title())
                    .append(a.optional() ? " (optional)" : "")
                    .append(" | ").append(methods)
                    .append(" | [").append(folder).append("/README.md](").append(folder).append("/README.md)")
                    .append(" | ").append(files)
                    .append(" | ").append(a.requires().isEmpty() ? "-" : String.join(", ", a.requires()))
                    .append(" |\n");
        }
        return t.toString().stripTrailing();
    }
}
