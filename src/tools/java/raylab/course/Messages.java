package raylab.course;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Failure messages in the students' terms, the same for visible and hidden tests: JUnit's
 * assertion residue is turned into the visible tests' "expected / got" lines, and rays are
 * written as in the lecture (p, d and the range of t) rather than as Java's record syntax.
 */
public final class Messages {
    /** JUnit's suffix of assertTrue / assertFalse, which adds nothing to a message that says what was expected. */
    private static final Pattern BOOLEAN = Pattern.compile(" ?==> expected: <(?:true|false)> but was: <(?:true|false)>");
    /** JUnit's suffix of assertEquals / assertSame with a message. */
    private static final Pattern EQUALS = Pattern.compile(" ?==> expected: <(.*?)> but was: <(.*?)>", Pattern.DOTALL);
    /** JUnit's whole message of an assertion without a message. */
    private static final Pattern BARE = Pattern.compile("^expected: <(.*?)> but was: <(.*?)>", Pattern.DOTALL);
    /** {@code Ray.toString()}. */
    private static final Pattern RAY = Pattern.compile("Ray\\[p=(\\([^)]*\\)), d=(\\([^)]*\\)), t in (\\[[^\\]]*\\])\\]");

    private Messages() {
    }

    /** The message with JUnit residue and raw rays rewritten; other text unchanged. */
    public static String plain(String message) {
        if (message == null || message.isEmpty()) {
            return message == null ? "" : message;
        }
        String m = BOOLEAN.matcher(message).replaceAll("");
        m = EQUALS.matcher(m).replaceAll(r -> Matcher.quoteReplacement(
                "\n  expected: " + r.group(1) + "\n  got:      " + r.group(2)));
        m = BARE.matcher(m).replaceAll(r -> Matcher.quoteReplacement(
                "expected: " + r.group(1) + "\n  got:      " + r.group(2)));
        m = RAY.matcher(m).replaceAll(r -> Matcher.quoteReplacement(
                "p=" + r.group(1) + " d=" + r.group(2) + " t in " + r.group(3)));
        return m;
    }
}
