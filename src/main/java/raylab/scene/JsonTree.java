package raylab.scene;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.StreamReadFeature;

/**
 * A JSON document read into a small tree whose every node knows its line, column and JSON path,
 * so that the scene loader can say exactly where a problem is. Jackson's own tree keeps no
 * locations, so this reads Jackson's token stream. Syntax errors become one-line
 * {@link SceneException}s in the loader's format, never Jackson's multi-line messages.
 *
 * <p>One parser for one format: JSON with the locations of its nodes.
 */
final class JsonTree {

    /** The kinds of JSON values. */
    enum Kind { OBJECT, ARRAY, STRING, NUMBER, BOOLEAN, NULL }

    /** A line and column, both counted from 1. */
    record Pos(int line, int column) {
        @Override
        public String toString() {
            return "line " + line + ", column " + column;
        }
    }

    /** One JSON value with where it starts in the file and its JSON path ($.a.b[2]). */
    static final class Node {
        final Kind kind;
        final String path;
        final Pos pos;
        /** Object members in file order (objects only). */
        final Map<String, Node> fields;
        /** Where each object key starts (objects only). */
        final Map<String, Pos> keyPos;
        /** Array elements (arrays only). */
        final List<Node> items;
        /** The string's value, or a number's text as written in the file. */
        final String text;
        final double number;
        final boolean bool;

        private Node(Kind kind, String path, Pos pos, String text, double number, boolean bool) {
            this.kind = kind;
            this.path = path;
            this.pos = pos;
            this.text = text;
            this.number = number;
            this.bool = bool;
            this.fields = kind == Kind.OBJECT ? new LinkedHashMap<>() : Collections.emptyMap();
            this.keyPos = kind == Kind.OBJECT ? new LinkedHashMap<>() : Collections.emptyMap();
            this.items = kind == Kind.ARRAY ? new ArrayList<>() : Collections.emptyList();
        }

        boolean has(String key) {
            return fields.containsKey(key);
        }

        Node get(String key) {
            return fields.get(key);
        }

        /** The path of a member of this object, whether or not it exists. */
        String childPath(String key) {
            return JsonTree.childPath(path, key);
        }

        /** "an object", "the string \"x\"", "the number 5", "true", "null"... for messages. */
        String describe() {
            switch (kind) {
                case OBJECT:
                    return "an object";
                case ARRAY:
                    return items.isEmpty() ? "an empty array" : "an array";
                case STRING:
                    return "the string " + quote(text);
                case NUMBER:
                    return "the number " + text;
                case BOOLEAN:
                    return bool ? "true" : "false";
                default:
                    return "null";
            }
        }
    }

    /**
     * Longest number accepted, in characters. Far above Jackson's default (1,000) so that long
     * numbers are read and reported at their own place like any other value (a 1,500-digit
     * integer is "too large", a 1,500-digit fraction is just a fraction); longer ones are refused.
     */
    static final int MAX_NUMBER_LENGTH = 100_000;

    private static final JsonFactory FACTORY = JsonFactory.builder()
            .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
            .streamReadConstraints(StreamReadConstraints.builder()
                    .maxNumberLength(MAX_NUMBER_LENGTH).build())
            .build();

    private static final Pattern PLAIN_KEY = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$]*");
    private static final Pattern UNEXPECTED_CHAR =
            Pattern.compile("^Unexpected character \\('(.)' \\(code (\\d+)[^)]*\\)\\)");
    private static final Pattern QUOTED = Pattern.compile("'([^']*)'");
    private static final Pattern CLOSE_MARKER =
            Pattern.compile("^Unexpected close marker '(.)': expected '(.)'");
    private static final Pattern CODE = Pattern.compile("code (\\d+)");

    private final String text;
    private final String file;
    private final int[] lineStarts;
    private final Deque<Node> open = new ArrayDeque<>();
    private JsonParser parser;
    /** The JSON path of what is being read, for syntax errors. */
    private String where = "$";
    /** Offset of the last token read (for errors that Jackson places badly), or -1. */
    private int lastToken = -1;

    private JsonTree(String text, String file) {
        this.text = text;
        this.file = file;
        List<Integer> starts = new ArrayList<>();
        starts.add(0);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n' || (c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n'))) {
                starts.add(i + 1);
            }
        }
        lineStarts = starts.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * Reads one JSON value that must fill the whole text.
     *
     * @param file the file name to start error messages with
     */
    static Node read(String text, String file) throws SceneException {
        return new JsonTree(text, file).readDocument();
    }

    /** The JSON path of member {@code key} of the object at {@code path}. */
    static String childPath(String path, String key) {
        if (PLAIN_KEY.matcher(key).matches()) {
            return path + "." + key;
        }
        return path + "[" + quote(key) + "]";
    }

    /** A string in double quotes with JSON escapes, shortened if long. */
    static String quote(String s) {
        String t = s.length() > 60 ? s.substring(0, 57) + "..." : s;
        StringBuilder b = new StringBuilder("\"");
        for (int i = 0; i < t.length(); i++) {
            char c = t.charAt(i);
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (Display.needsEscape(t, i)) {
                b.append(Display.escape(String.valueOf(c)));
            } else {
                b.append(c);
            }
        }
        return b.append('"').toString();
    }

    /**
     * A number as written, for messages: numbers longer than 40 characters are shortened to their
     * first 20 characters and their length.
     */
    static String shortNumber(String raw) {
        return raw.length() <= 40 ? raw : raw.substring(0, 20) + "... (" + raw.length() + " characters)";
    }

    private Node readDocument() throws SceneException {
        try (JsonParser p = FACTORY.createParser(text)) {
            parser = p;
            JsonToken t = p.nextToken();
            Node root = readValue(t, "$");
            where = "$";
            int end = (int) Math.min(text.length(), Math.max(0, p.currentLocation().getCharOffset()));
            while (end < text.length() && isJsonWhitespace(text.charAt(end))) {
                end++;
            }
            if (end < text.length()) {
                throw error(pos(end), "$", "unexpected text after the end of the top-level value"
                        + " (a scene file holds exactly one JSON object)");
            }
            return root;
        } catch (JsonProcessingException e) {
            throw translate(e);
        } catch (IOException e) {
            throw new SceneException(file + ": cannot read: " + firstLine(e.getMessage()));
        }
    }

    private Node readValue(JsonToken t, String path) throws IOException, SceneException {
        Pos pos = tokenPos();
        where = path;
        switch (t) {
            case START_OBJECT: {
                Node node = new Node(Kind.OBJECT, path, pos, null, 0, false);
                open.push(node);
                JsonToken k;
                while ((k = parser.nextToken()) != JsonToken.END_OBJECT) {
                    String key = parser.currentName();
                    Pos keyPos = tokenPos();
                    String child = childPath(path, key);
                    where = child;
                    Node value = readValue(parser.nextToken(), child);
                    node.fields.put(key, value);
                    node.keyPos.put(key, keyPos);
                    where = path;
                }
                open.pop();
                return node;
            }
            case START_ARRAY: {
                Node node = new Node(Kind.ARRAY, path, pos, null, 0, false);
                open.push(node);
                JsonToken e;
                while ((e = parser.nextToken()) != JsonToken.END_ARRAY) {
                    node.items.add(readValue(e, path + "[" + node.items.size() + "]"));
                    where = path;
                }
                open.pop();
                return node;
            }
            case VALUE_STRING:
                return new Node(Kind.STRING, path, pos, parser.getText(), 0, false);
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT: {
                String raw = shortNumber(parser.getText());
                double d = parser.getDoubleValue();
                if (!Double.isFinite(d)) {
                    throw error(pos, path, "the number " + raw
                            + " is too large (it overflows to infinity); numbers must be finite");
                }
                return new Node(Kind.NUMBER, path, pos, raw, d, false);
            }
            case VALUE_TRUE:
            case VALUE_FALSE:
                return new Node(Kind.BOOLEAN, path, pos, null, 0, t == JsonToken.VALUE_TRUE);
            case VALUE_NULL:
                return new Node(Kind.NULL, path, pos, null, 0, false);
            default:
                throw error(pos, path, "unexpected " + t);
        }
    }

    private static boolean isJsonWhitespace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    /**
     * The path of the value that starts at offset start while Jackson was still reading the key or
     * the comma before it (Jackson reads a member's key and the first token of its value in one step).
     */
    private String valuePath(int start) {
        Node in = open.peek();
        if (in == null || !where.equals(in.path)) {
            return where;
        }
        if (in.kind == Kind.ARRAY) {
            return in.path + "[" + in.items.size() + "]";
        }
        int i = skipBackWhitespace(start - 1);
        if (i < 0 || text.charAt(i) != ':') {
            return where;
        }
        String key = keyBefore(i);
        return key == null ? where : childPath(in.path, key);
    }

    private Pos tokenPos() {
        long off = parser.currentTokenLocation().getCharOffset();
        lastToken = (int) Math.max(0, Math.min(off, text.length()));
        return pos(off);
    }

    /** Line and column of a character offset (columns count characters, from 1). */
    Pos pos(long offset) {
        int off = (int) Math.max(0, Math.min(offset, text.length()));
        int lo = 0;
        int hi = lineStarts.length - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (lineStarts[mid] <= off) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return new Pos(lo + 1, off - lineStarts[lo] + 1);
    }

    private SceneException error(Pos pos, String path, String message) {
        return new SceneException(file + ":" + pos.line + ":" + pos.column + ": " + path + ": " + message);
    }

    /** Jackson's syntax error as one line of our own. */
    private SceneException translate(JsonProcessingException e) {
        String m = e.getOriginalMessage() == null ? "" : e.getOriginalMessage();
        long off = e.getLocation() == null ? text.length() : e.getLocation().getCharOffset();
        if (off < 0) {
            off = text.length();
        }
        Matcher uc = UNEXPECTED_CHAR.matcher(m);
        Matcher q = QUOTED.matcher(m);
        Matcher cm = CLOSE_MARKER.matcher(m);
        Node inside = open.peek();

        if (m.startsWith("Duplicate field") && q.find()) {
            String key = q.group(1);
            int start = keyStartBefore((int) off);
            Pos first = inside != null ? inside.keyPos.get(key) : null;
            String path = inside != null ? childPath(inside.path, key) : where;
            return error(start >= 0 ? pos(start) : pos(off), path, "duplicate key " + quote(key)
                    + (first != null ? " (first given at " + first + ")" : "")
                    + "; each key may appear only once in an object");
        }
        if (m.startsWith("Non-standard token") && q.find()) {
            String tok = q.group(1);
            int start = wordStartBefore((int) off);
            return error(pos(start), valuePath(start), tok
                    + " is not allowed: numbers must be finite (JSON has no NaN or Infinity)");
        }
        if (m.startsWith("Unrecognized token") && q.find()) {
            String tok = q.group(1);
            int start = wordStartBefore((int) off);
            return error(pos(start), valuePath(start), "unrecognized word " + quote(tok)
                    + ": expected a value (a string in double quotes, a number, an object, an array,"
                    + " true, false or null)");
        }
        if (m.contains("was expecting double-quote to start field name") && uc.find()) {
            char c = uc.group(1).charAt(0);
            if (c == '}') {
                int comma = skipBackWhitespace((int) off - 1);
                return error(pos(comma >= 0 && text.charAt(comma) == ',' ? comma : off), where,
                        "trailing comma: remove the ',' before '}'");
            }
            if (c == '\'') {
                return error(pos(off), where, "keys must be in double quotes, not single quotes");
            }
            return error(pos(off), where, "expected a key in double quotes, got '" + c + "'");
        }
        if (uc.find() && uc.group(1).charAt(0) == '\uFEFF') {
            return error(pos(off), valuePath((int) off), "a byte-order mark (U+FEFF) in the middle of the"
                    + " text; it may only stand at the very start of the file");
        }
        uc.reset();
        if (m.contains("expected a valid value") && uc.find()) {
            char c = uc.group(1).charAt(0);
            if (c == ']' && inside != null && inside.kind == Kind.ARRAY && !inside.items.isEmpty()) {
                int comma = skipBackWhitespace((int) off - 1);
                return error(pos(comma >= 0 && text.charAt(comma) == ',' ? comma : off), where,
                        "trailing comma: remove the ',' before ']'");
            }
            if (c == '.') {
                return error(pos(off), valuePath((int) off), "malformed number: write a digit"
                        + " before the decimal point (0.5, not .5)");
            }
            return error(pos(off), valuePath((int) off), "expected a value, got '" + c + "'");
        }
        if (m.contains("was expecting a colon")) {
            String key = keyBefore((int) off);
            String path = inside != null && key != null ? childPath(inside.path, key) : where;
            return error(pos(off), path, "missing ':' after the key"
                    + (key != null ? " " + quote(key) : ""));
        }
        if (m.contains("was expecting comma to separate Object entries")) {
            return error(pos(off), where, "missing ',' between two members of the object"
                    + (uc.find() ? " (found '" + uc.group(1) + "')" : ""));
        }
        if (m.contains("was expecting comma to separate Array entries")) {
            return error(pos(off), where, "missing ',' between two elements of the array"
                    + (uc.find() ? " (found '" + uc.group(1) + "')" : ""));
        }
        if (m.startsWith("Unexpected end-of-input")) {
            if (m.contains("closing quote")) {
                return error(pos(off), where, "unexpected end of file inside a string (missing"
                        + " closing '\"')");
            }
            if (inside != null) {
                boolean obj = inside.kind == Kind.OBJECT;
                return error(pos(off), where, "unexpected end of file: the " + (obj ? "object" : "array")
                        + " opened at " + inside.pos + " is not closed (missing '" + (obj ? '}' : ']')
                        + "')");
            }
            return error(pos(off), where, "unexpected end of file");
        }
        if (cm.find()) {
            String got = cm.group(1);
            String want = cm.group(2);
            String opened = inside != null ? " the " + (inside.kind == Kind.OBJECT ? "object" : "array")
                    + " opened at " + inside.pos : "";
            return error(pos(off), where, "'" + got + "' does not match: expected '" + want
                    + "' to close" + opened);
        }
        if (m.startsWith("Illegal unquoted character")) {
            Matcher code = CODE.matcher(m);
            int c = code.find() ? Integer.parseInt(code.group(1)) : -1;
            String what = c == 10 || c == 13 ? "a line break (write \\n; a string ends on the line"
                    + " it starts)" : c == 9 ? "a tab (write \\t)"
                    : "control character " + c + " (write \\u" + String.format("%04x", c) + ")";
            return error(pos(off), where, "a string must not contain " + what);
        }
        if (m.startsWith("Unrecognized character escape") && q.find()) {
            return error(pos(off - 1), where, "invalid escape '\\" + q.group(1)
                    + "' in a string (valid: \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
        }
        if (m.contains("numeric value")) {
            String detail = m.substring(m.lastIndexOf(':') + 1).trim();
            int start = wordStartBefore((int) off);
            return error(pos(start), valuePath(start), "malformed number: "
                    + (detail.isEmpty() ? m : Character.toLowerCase(detail.charAt(0)) + detail.substring(1)));
        }
        if (m.contains("nesting depth")) {
            return error(pos(off), "$", "the JSON is nested too deeply (more than "
                    + FACTORY.streamReadConstraints().getMaxNestingDepth() + " levels)");
        }
        if (m.contains("Number value length") || m.contains("number value length")) {
            // Jackson reports the place where it stopped, not where the number starts.
            int start = longNumberStart();
            return error(pos(start), valuePath(start), "a number with more than "
                    + MAX_NUMBER_LENGTH + " characters");
        }
        if (m.contains("comment")) {
            return error(pos(off), where, "comments are not allowed in JSON");
        }
        return error(pos(off), where, cleanup(m));
    }

    /** Jackson's message without its hints about features, sources and code points. */
    private static String cleanup(String m) {
        String s = firstLine(m);
        s = s.replaceAll(" ?\\(code \\d+[^)]*\\)", "");
        s = s.replaceAll(" ?\\((?:for|start marker)[^)]*\\)+", "");
        s = s.replaceAll("\\[Source:[^\\]]*\\]", "");
        s = s.replaceAll(":? ?enable `[^`]*`.*$", "");
        s = s.replaceAll(",? ?from `[^`]*`", "");
        s = s.trim();
        if (s.isEmpty()) {
            return "malformed JSON";
        }
        return "malformed JSON: " + Character.toLowerCase(s.charAt(0)) + s.substring(1);
    }

    static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        String line = nl < 0 ? s : s.substring(0, nl);
        int cr = line.indexOf('\r');
        return cr < 0 ? line : line.substring(0, cr);
    }

    /**
     * Where the over-long number starts: the first run of number characters longer than the limit
     * after the last token Jackson returned.
     */
    private int longNumberStart() {
        int from = lastToken < 0 ? 0 : lastToken;
        int run = 0;
        for (int i = from; i < text.length(); i++) {
            char c = text.charAt(i);
            if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E') {
                if (++run > MAX_NUMBER_LENGTH) {
                    return i - run + 1;
                }
            } else {
                run = 0;
            }
        }
        return from;
    }

    /** The index of the last non-whitespace character at or before i (or -1). */
    private int skipBackWhitespace(int i) {
        while (i >= 0 && i < text.length() && Character.isWhitespace(text.charAt(i))) {
            i--;
        }
        return Math.min(i, text.length() - 1);
    }

    /** The start of the word (letters, digits, sign, point) that ends just before offset end. */
    private int wordStartBefore(int end) {
        int i = Math.min(end, text.length());
        while (i > 0 && isWordChar(text.charAt(i - 1))) {
            i--;
        }
        return i;
    }

    private static boolean isWordChar(char c) {
        return Character.isLetterOrDigit(c) || c == '+' || c == '-' || c == '.' || c == '_';
    }

    /** The start (opening quote) of the quoted key that ends before the ':' near offset end. */
    private int keyStartBefore(int end) {
        int i = Math.min(end, text.length()) - 1;
        while (i >= 0 && (Character.isWhitespace(text.charAt(i)) || text.charAt(i) == ':')) {
            i--;
        }
        if (i < 0 || text.charAt(i) != '"') {
            return -1;
        }
        int j = i - 1;
        while (j >= 0 && !(text.charAt(j) == '"' && (j == 0 || text.charAt(j - 1) != '\\'))) {
            j--;
        }
        return j;
    }

    /** The text of the quoted key that ends before offset i, skipping whitespace, or null. */
    private String keyBefore(int i) {
        int close = skipBackWhitespace(i - 1);
        if (close < 0 || text.charAt(close) != '"') {
            return null;
        }
        int start = keyStartBefore(close + 1);
        return start < 0 ? null : text.substring(start + 1, close);
    }
}
