package raylab.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import raylab.course.Assignment;

/**
 * Text found only in the hidden classes (hidden tests, hidden data cases, hidden helpers): never
 * shown in a visible test's message or output, which are withheld when they contain any.
 */
final class HiddenText {
    static final String WITHHELD = "(withheld: it contains text of the hidden tests)";

    private final Set<String> texts;

    private HiddenText(Set<String> texts) {
        this.texts = texts;
    }

    /** None: nothing is withheld. */
    static final HiddenText NONE = new HiddenText(Set.of());

    /**
     * Text of the hidden classes that no visible class has: their names, and their text constants
     * with a space in them (messages, hints).
     */
    static HiddenText of(GraderSetup setup, List<Assignment> all) {
        Set<String> visibleClasses = new HashSet<>();
        for (Assignment a : all) {
            a.tests().visible().forEach(v -> visibleClasses.add(GraderSetup.testClassName(v)));
            visibleClasses.add(DataCases.visibleClassName(a.id()));
        }
        Set<String> hiddenClasses = new HashSet<>();
        setup.testClasses.values().forEach(l -> l.stream().filter(c -> !visibleClasses.contains(c))
                .forEach(hiddenClasses::add));
        Set<String> hidden = new HashSet<>();
        Set<String> shared = new HashSet<>();
        try (Stream<Path> s = Files.walk(setup.tests)) {
            for (Path p : (Iterable<Path>) s.filter(f -> f.toString().endsWith(".class"))::iterator) {
                String rel = setup.tests.relativize(p).toString().replace('\\', '/');
                String outer = GraderSetup.outer(rel.substring(0, rel.length() - 6).replace('/', '.'));
                boolean isHidden = hiddenClasses.contains(outer) || outer.startsWith("raylab.hidden.");
                Set<String> strings = ClassStrings.of(Files.readAllBytes(p));
                if (isHidden) {
                    hidden.addAll(strings);
                    hidden.add(outer);
                    hidden.add(outer.replace('.', '/'));
                } else {
                    shared.addAll(strings);
                }
            }
        } catch (IOException e) {
            return NONE;
        }
        Set<String> out = new HashSet<>();
        for (String h : hidden) {
            boolean name = h.contains("Hidden") || hiddenClasses.contains(h) || hiddenClasses.contains(h.replace('/', '.'));
            boolean text = h.length() >= 12 && h.indexOf(' ') >= 0 && !h.isBlank();
            if (!shared.contains(h) && (name || text)) {
                out.add(h);
            }
        }
        return new HiddenText(out);
    }

    /** A visible test's message and output, unless they contain text of the hidden tests. */
    GradeReport.Test withheld(GradeReport.Test t) {
        if (!"visible".equals(t.visibility())) {
            return t;
        }
        String m = withheld(t.message());
        String o = withheld(t.output());
        if (m.equals(t.message()) && o.equals(t.output())) {
            return t;
        }
        return new GradeReport.Test(t.milestone(), t.name(), t.kind(), t.maxScore(), t.score(), t.passed(), m, o,
                t.visibility(), t.millis(), t.file(), t.images(), withheld(t.note()), t.status());
    }

    /** {@code text}, or {@link #WITHHELD} when it contains text of the hidden tests. */
    String withheld(String text) {
        if (text == null || text.isEmpty()) {
            return text == null ? "" : text;
        }
        for (String h : texts) {
            if (text.contains(h)) {
                return WITHHELD;
            }
        }
        return text;
    }
}
