package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Every code block of the project's Markdown pages and of the starter's closes, as GitHub reads
 * them ({@link MarkdownFences}); the release's verification checks the starter's too.
 */
class MarkdownFencesTest {
    @Test
    void aClosingFenceWithTextAfterItDoesNotClose() {
        String page = "# Start\n\n```sh\n./raylab check\n``` Then read the table.\n\n## Milestones\n| 1 | sphere |\n";
        assertEquals(List.of("README.md:5: this line starts with ``` but has text after it, so it does not end the code"
                + " block opened at line 3: the lines after it render as code (put the text on a line of its own)",
                "README.md:3: the code block opened here never closes, so the rest of the page renders as code"),
                MarkdownFences.unclosed("README.md", page));
        // With a block after it, the next fence ends the first block: no block is left open, and the line is still named.
        assertEquals(List.of("README.md:5: this line starts with ``` but has text after it, so it does not end the code"
                + " block opened at line 3: the lines after it render as code (put the text on a line of its own)"),
                MarkdownFences.unclosed("README.md", page + "\n```sh\n./raylab render\n```\n"));
        assertEquals(List.of(), MarkdownFences.unclosed("README.md", page.replace("``` Then", "```\nThen")));
    }

    @Test
    void fencesCloseOnlyWithTheirOwnCharacterAndLength() {
        assertEquals(List.of(), MarkdownFences.unclosed("a.md", "````md\n```sh\nx\n```\n````\n"),
                "a longer fence holds a shorter one");
        assertEquals(List.of(), MarkdownFences.unclosed("a.md", "~~~\n```\n~~~  \n"), "tildes close tildes, spaces after");
        assertEquals(List.of("a.md:1: the code block opened here never closes, so the rest of the page renders as code"),
                MarkdownFences.unclosed("a.md", "```java\nint x;\n~~~\n"));
        assertEquals(List.of("a.md:2: the code block opened here never closes, so the rest of the page renders as code"),
                MarkdownFences.unclosed("a.md", "text\n   ````\ncode\n```\n"), "three spaces of indent still open one");
        assertEquals(List.of(), MarkdownFences.unclosed("a.md", "```inline``` is not a fence\n"),
                "an info string with a backtick makes the line inline code");
    }

    @Test
    void everyPageOfTheProjectClosesItsCodeBlocks() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        List<String> problems = new ArrayList<>();
        int pages = 0;
        for (String top : List.of("README.md", "assignments", "docs", "grader", "scenes", "src")) {
            try (Stream<Path> s = Files.walk(root.resolve(top))) {
                for (Path p : s.filter(f -> f.toString().endsWith(".md") && Files.isRegularFile(f)).toList()) {
                    problems.addAll(MarkdownFences.unclosed(root.relativize(p).toString(), Files.readString(p)));
                    pages++;
                }
            }
        }
        assertTrue(pages > 15, "the project's Markdown pages: " + pages);
        assertEquals(List.of(), problems, pages + " pages read");
    }

    @Test
    void everyPageOfTheStarterClosesItsCodeBlocks() throws IOException {
        Map<String, byte[]> starter = Release.build(Path.of("").toAbsolutePath()).files();
        List<String> problems = new ArrayList<>();
        int pages = 0;
        for (Map.Entry<String, byte[]> e : starter.entrySet()) {
            if (e.getKey().endsWith(".md")) {
                problems.addAll(MarkdownFences.unclosed(e.getKey(), new String(e.getValue(), StandardCharsets.UTF_8)));
                pages++;
            }
        }
        assertTrue(starter.containsKey("README.md"), "the starter's README");
        assertEquals(List.of(), problems, pages + " pages read");
    }
}
