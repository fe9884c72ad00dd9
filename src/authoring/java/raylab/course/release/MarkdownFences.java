package raylab.course.release;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Code blocks of a Markdown page that do not end where they seem to, as CommonMark (and so GitHub)
 * reads them: a fence of three or more backticks or tildes, indented at most three spaces, opens a
 * block that only a line of the same character, at least as long and followed by nothing but
 * spaces or tabs, closes (CommonMark's "Fenced code blocks"; GitHub's parser, cmark-gfm, scans a
 * closing fence as {@code [`]{3,} / [ \t]*[\r\n]} in {@code src/scanners.re}). A closing fence
 * with text after it ("``` At the start ...") is a line of code, so the page renders as code up to
 * the next fence: the starter's README once showed its milestone table as code that way.
 */
final class MarkdownFences {
    private static final Pattern OPEN = Pattern.compile("^ {0,3}(`{3,}|~{3,})(.*)$");

    private MarkdownFences() {
    }

    /**
     * "PATH:LINE: ..." for the first line inside a code block that starts with the block's fence and
     * has text after it (it reads as the block's end and is a line of code: a block written to end
     * there goes on to the next fence, and every block after it is off by one), and for a block
     * that never closes; empty when every block ends where it seems to.
     */
    static List<String> unclosed(String path, String text) {
        List<String> out = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        String fence = null;
        int opened = 0;
        boolean named = false;
        for (int i = 0; i < lines.length; i++) {
            Matcher m = OPEN.matcher(lines[i]);
            if (fence == null) {
                // An info string after backticks may not hold a backtick (then it is inline code).
                if (m.matches() && !(m.group(1).charAt(0) == '`' && m.group(2).contains("`"))) {
                    fence = m.group(1);
                    opened = i + 1;
                    named = false;
                }
            } else if (m.matches() && m.group(1).charAt(0) == fence.charAt(0) && m.group(1).length() >= fence.length()) {
                if (m.group(2).isBlank()) {
                    fence = null;
                } else if (!named) {
                    named = true; // the fences after it are off by one because of it: it alone is named
                    out.add(path + ":" + (i + 1) + ": this line starts with " + fence + " but has text after it, so it"
                            + " does not end the code block opened at line " + opened + ": the lines after it render as"
                            + " code (put the text on a line of its own)");
                }
            }
        }
        if (fence != null) {
            out.add(path + ":" + opened + ": the code block opened here never closes, so the rest of the page renders as"
                    + " code");
        }
        return out;
    }
}
