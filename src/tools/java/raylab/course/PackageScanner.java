package raylab.course;

/**
 * Finds the {@code package} declaration of a Java source file with one linear pass (no regular
 * expression, no recursion): Unicode escapes are translated as javac does (JLS 3.3), then
 * whitespace, {@code //} and {@code /* *}{@code /} comments are skipped up to the first token.
 * Time and memory are linear in the file's length whatever its comments hold.
 */
public final class PackageScanner {
    private PackageScanner() {
    }

    /** The declared package ("" for none or an unreadable declaration). */
    public static String packageOf(String source) {
        String s = unescape(source);
        int n = s.length();
        int i = 0;
        if (i < n && s.charAt(i) == '\uFEFF') {
            i++;
        }
        while (i < n) {
            char c = s.charAt(i);
            int after = afterComment(s, i);
            if (after < 0) {
                return "";
            } else if (Character.isWhitespace(c) || c == '\u001A') {
                i++;
            } else if (after > i) {
                i = after;
            } else {
                break;
            }
        }
        if (!s.startsWith("package", i) || i + 7 >= n || Character.isJavaIdentifierPart(s.charAt(i + 7))) {
            return "";
        }
        i += 7;
        StringBuilder name = new StringBuilder();
        boolean needIdentifier = true;
        while (i < n) {
            char c = s.charAt(i);
            int after = afterComment(s, i);
            if (after < 0) {
                return "";
            } else if (Character.isWhitespace(c)) {
                i++;
            } else if (after > i) {
                i = after;
            } else if (needIdentifier && Character.isJavaIdentifierStart(c)) {
                while (i < n && Character.isJavaIdentifierPart(s.charAt(i))) {
                    name.append(s.charAt(i++));
                }
                needIdentifier = false;
            } else if (!needIdentifier && c == '.') {
                name.append('.');
                needIdentifier = true;
                i++;
            } else if (!needIdentifier && c == ';') {
                return name.toString();
            } else {
                return "";
            }
        }
        return "";
    }

    /**
     * Where the comment that starts at {@code i} ends: at its line's end ({@code //}) or after its
     * {@code *}{@code /}; {@code i} when no comment starts there; −1 when a block comment never ends.
     */
    private static int afterComment(String s, int i) {
        int n = s.length();
        if (s.charAt(i) != '/' || i + 1 >= n) {
            return i;
        }
        if (s.charAt(i + 1) == '/') {
            int j = i;
            while (j < n && s.charAt(j) != '\n' && s.charAt(j) != '\r') {
                j++;
            }
            return j;
        }
        if (s.charAt(i + 1) == '*') {
            int end = s.indexOf("*/", i + 2);
            return end < 0 ? -1 : end + 2;
        }
        return i;
    }

    /** Translates Unicode escapes ({@code \}{@code uXXXX}, any number of u's) as the compiler does. */
    public static String unescape(String s) {
        if (s.indexOf('\\') < 0) {
            return s;
        }
        StringBuilder b = new StringBuilder(s.length());
        int n = s.length();
        int i = 0;
        while (i < n) {
            char c = s.charAt(i);
            if (c != '\\') {
                b.append(c);
                i++;
                continue;
            }
            // Count the backslashes: an escape needs an odd number before the 'u'.
            int j = i;
            while (j < n && s.charAt(j) == '\\') {
                j++;
            }
            int slashes = j - i;
            b.append(s, i, j - 1);
            i = j - 1;
            if (slashes % 2 == 1 && j < n && s.charAt(j) == 'u') {
                int k = j;
                while (k < n && s.charAt(k) == 'u') {
                    k++;
                }
                if (k + 4 <= n && isHex(s, k)) {
                    b.append((char) Integer.parseInt(s.substring(k, k + 4), 16));
                    i = k + 4;
                    continue;
                }
            }
            b.append('\\');
            i++;
        }
        return b.toString();
    }

    private static boolean isHex(String s, int k) {
        for (int m = k; m < k + 4; m++) {
            if (Character.digit(s.charAt(m), 16) < 0) {
                return false;
            }
        }
        return true;
    }
}
