package raylab.study;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;

/** The study's Markdown report: a header, the conclusions, then one section per experiment. */
final class Report {
    private final List<String> conclusions = new ArrayList<>();
    private final StringBuilder body = new StringBuilder();
    private final List<String> plots = new ArrayList<>();

    /** One bullet for the conclusions at the top: which choice to make, its cost, where the curve bends. */
    void conclude(String bullet) {
        conclusions.add(bullet);
    }

    void section(String title) {
        body.append("\n## ").append(title).append("\n\n");
    }

    void paragraph(String text) {
        body.append(text.strip()).append("\n\n");
    }

    void plot(String file, String caption) {
        plots.add(file);
        body.append("![").append(caption).append("](").append(file).append(")\n\n");
    }

    /** A Markdown table; the first row is the header. */
    void table(List<String[]> rows) {
        String[] head = rows.get(0);
        body.append("| ").append(String.join(" | ", head)).append(" |\n|");
        for (int i = 0; i < head.length; i++) {
            body.append(i == 0 ? "---|" : "---:|");
        }
        body.append('\n');
        for (String[] r : rows.subList(1, rows.size())) {
            body.append("| ").append(String.join(" | ", r)).append(" |\n");
        }
        body.append('\n');
    }

    List<String> plots() {
        return List.copyOf(plots);
    }

    List<String> conclusions() {
        return List.copyOf(conclusions);
    }

    String markdown(String title, List<String> header) {
        StringBuilder sb = new StringBuilder();
        sb.append("# ").append(title).append("\n\n");
        for (String h : header) {
            sb.append(h).append("  \n");
        }
        sb.append("\n## Conclusions\n\n");
        for (String c : conclusions) {
            sb.append("- ").append(c.strip()).append('\n');
        }
        sb.append(body);
        return sb.toString();
    }

    /** Writes text to a temporary file beside the target, then renames it over the target. */
    static void writeAtomically(Path target, String text) throws IOException {
        Path abs = target.toAbsolutePath();
        Files.createDirectories(abs.getParent());
        Path tmp = Files.createTempFile(abs.getParent(), "." + abs.getFileName() + ".", ".tmp");
        try {
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            try {
                Files.move(tmp, abs, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
