package raylab.course.release;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;

import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * What the student starter contains, as {@code assignments/release.json} says (format in
 * docs/instructors.md): paths to copy, paths to leave out, paths that must never appear, files to
 * mark executable, and the template of the starter's README. The visible tests listed in the
 * assignment.json files are added to {@code include} implicitly.
 *
 * @param include        globs of files to copy
 * @param exclude        globs of files not to copy although {@code include} matches them
 * @param never          globs that must match no file of the starter (checked after writing)
 * @param executable     files to mark executable in the starter (all others are not)
 * @param readmeTemplate the template the starter's README.md is generated from
 */
public record ReleaseSpec(@JsonProperty(required = true) List<String> include, List<String> exclude,
        List<String> never, List<String> executable, @JsonProperty(required = true) String readmeTemplate,
        String about) {
    /** Where the release description lives, relative to the project root. */
    public static final String FILE = "assignments/release.json";

    public ReleaseSpec {
        include = List.copyOf(include);
        exclude = exclude == null ? List.of() : List.copyOf(exclude);
        never = never == null ? List.of() : List.copyOf(never);
        executable = executable == null ? List.of() : List.copyOf(executable);
    }

    /** Reads {@code assignments/release.json}; a malformed file is an IOException with one line. */
    public static ReleaseSpec load(Path projectRoot) throws IOException {
        Path file = projectRoot.resolve(FILE);
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": missing (it says what the student starter contains)");
        }
        ObjectMapper json = new ObjectMapper().enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);
        try {
            return json.readValue(file.toFile(), ReleaseSpec.class);
        } catch (JsonProcessingException e) {
            String where = e.getLocation() == null ? "" : ":" + e.getLocation().getLineNr();
            throw new IOException(file + where + ": " + e.getOriginalMessage().split("\n")[0]);
        }
    }

    /** Whether the relative path (with '/') matches any of the globs. */
    public static boolean matchesAny(List<String> globs, String relativePath) {
        for (String g : globs) {
            if (glob(g).matcher(relativePath).matches()) {
                return true;
            }
        }
        return false;
    }

    /** A glob as a regular expression: '**' any run of characters, '*' and '?' within one name. */
    static Pattern glob(String glob) {
        StringBuilder re = new StringBuilder();
        for (int i = 0; i < glob.length(); i++) {
            char c = glob.charAt(i);
            if (c == '*' && i + 1 < glob.length() && glob.charAt(i + 1) == '*') {
                // "**/" also matches nothing, so "**/x" matches "x" at the top.
                if (i + 2 < glob.length() && glob.charAt(i + 2) == '/') {
                    re.append("(?:.*/)?");
                    i += 2;
                } else {
                    re.append(".*");
                    i++;
                }
            } else if (c == '*') {
                re.append("[^/]*");
            } else if (c == '?') {
                re.append("[^/]");
            } else {
                re.append(Pattern.quote(String.valueOf(c)));
            }
        }
        return Pattern.compile(re.toString());
    }
}
