package raylab.scene;

import java.nio.file.Path;

/**
 * Names, paths and other user-given text made safe to echo in a one-line message: control
 * characters (line breaks included), Unicode line and paragraph separators, bidirectional
 * overrides and lone surrogates are written as escapes ({@code \n}, {@code \t}, {@code \r},
 * {@code \}{@code uXXXX}); everything else is kept as it is.
 */
public final class Display {
    private Display() {
    }

    /** The text with every character that could break or disguise a line escaped. */
    public static String escape(String s) {
        if (s == null) {
            return "null";
        }
        int i = 0;
        while (i < s.length() && !needsEscape(s, i)) {
            i++;
        }
        if (i == s.length()) {
            return s;
        }
        StringBuilder b = new StringBuilder(s.length() + 16).append(s, 0, i);
        for (; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!needsEscape(s, i)) {
                b.append(c);
            } else if (c == '\n') {
                b.append("\\n");
            } else if (c == '\r') {
                b.append("\\r");
            } else if (c == '\t') {
                b.append("\\t");
            } else {
                b.append(String.format("\\u%04x", (int) c));
            }
        }
        return b.toString();
    }

    /** The most characters {@link #text} keeps of one text. */
    public static final int TEXT_MAX = 16 * 1024;

    /**
     * Text of several lines from untrusted code (a student's failure message or printed output),
     * made safe for every output (JSON, HTML, CSV, a terminal): line breaks ({@code \n}, and
     * {@code \r\n} as one) and tabs are kept, every other character {@link #escape} escapes is
     * escaped the same way (NUL, ESC, a lone CR, bidirectional overrides...), and the text is cut
     * after {@link #TEXT_MAX} characters (not inside a surrogate pair or an escape) with a note
     * saying how much was left out. Null stays null.
     */
    public static String text(String s) {
        if (s == null) {
            return null;
        }
        StringBuilder b = new StringBuilder(Math.min(s.length(), TEXT_MAX) + 40);
        int i = 0;
        while (i < s.length() && b.length() < TEXT_MAX) {
            char c = s.charAt(i);
            if (c == '\r' && i + 1 < s.length() && s.charAt(i + 1) == '\n') {
                i++; // \r\n: the \n is kept
            } else if (c == '\n' || c == '\t' || !needsEscape(s, i)) {
                b.append(c);
                i++;
                if (Character.isHighSurrogate(c) && i < s.length()) {
                    b.append(s.charAt(i++)); // a pair, whole (needsEscape said it is one)
                }
            } else {
                b.append(escape(String.valueOf(c)));
                i++;
            }
        }
        if (i < s.length()) {
            b.append("\n(").append(s.length() - i).append(" more characters cut)");
        }
        return b.length() == s.length() && i == s.length() ? s : b.toString();
    }

    /** A path as given, escaped as {@link #escape(String)} does. */
    public static String path(Path p) {
        return escape(String.valueOf(p));
    }

    /** Whether the character at i must be escaped. */
    static boolean needsEscape(String s, int i) {
        char c = s.charAt(i);
        if (c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == '\u2028' || c == '\u2029'
                || (c >= '\u202a' && c <= '\u202e') || (c >= '\u2066' && c <= '\u2069')
                || c == '\ufeff') {
            return true;
        }
        if (Character.isHighSurrogate(c)) {
            return i + 1 >= s.length() || !Character.isLowSurrogate(s.charAt(i + 1));
        }
        if (Character.isLowSurrogate(c)) {
            return i == 0 || !Character.isHighSurrogate(s.charAt(i - 1));
        }
        return false;
    }

    /** A number as scene messages show it: a whole number without ".0", else Java's shortest form. */
    public static String number(double d) {
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return Long.toString((long) d);
        }
        return Double.toString(d);
    }

    /** A number as {@code raylab trace} shows it: six significant digits, trailing zeros dropped. */
    public static String traced(double v) {
        return Double.isFinite(v) ? String.format("%.6g", v).replaceFirst("(\\.\\d*?)0+$", "$1").replaceFirst("\\.$", "")
                : Double.toString(v);
    }
}
