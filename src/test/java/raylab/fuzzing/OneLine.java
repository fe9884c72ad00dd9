package raylab.fuzzing;

import raylab.scene.Display;

/** The property every fuzz test checks: a failure is one line that names its file. */
public final class OneLine {
    private OneLine() {
    }

    /**
     * Fails (with an AssertionError, which the fuzzer reports as a finding) unless the message is
     * one line starting with {@code file}.
     *
     * @param strict also refuse characters that terminals show as breaks or hide (every character
     *     {@link Display#escape} escapes): the messages the command line prints
     */
    public static void check(String message, String file, boolean strict, Throwable cause) {
        if (message == null || message.isBlank()) {
            throw new AssertionError("an empty message", cause);
        }
        if (message.indexOf('\n') >= 0 || message.indexOf('\r') >= 0) {
            throw new AssertionError("a message of more than one line: " + Display.escape(message), cause);
        }
        if (strict && !Display.escape(message).equals(message)) {
            throw new AssertionError("a message with unescaped control characters: "
                    + Display.escape(message), cause);
        }
        if (file != null && !message.startsWith(file)) {
            throw new AssertionError("a message that does not start with " + file + ": "
                    + Display.escape(message), cause);
        }
    }
}
