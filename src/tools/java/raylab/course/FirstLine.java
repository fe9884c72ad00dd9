package raylab.course;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * The first non-blank line a child process wrote to a stream, which is read to its end by a thread
 * of its own so that the child never blocks on a full pipe: why a JVM did not start ("Unrecognized
 * VM option ...", "Error: Could not find or load main class ..."), for the course staff. At most
 * {@link #MAX} characters, control characters dropped; the rest of the stream is read and dropped.
 */
final class FirstLine {
    /** The longest line kept, in characters. */
    static final int MAX = 300;

    private final Thread reader;
    private final StringBuilder line = new StringBuilder();
    private boolean done;

    FirstLine(InputStream in) {
        reader = new Thread(() -> read(in), "raylab-first-line");
        reader.setDaemon(true);
        reader.start();
    }

    private void read(InputStream in) {
        byte[] buf = new byte[4096];
        try (in) {
            for (int n; (n = in.read(buf)) > 0;) {
                synchronized (this) {
                    for (char c : new String(buf, 0, n, StandardCharsets.UTF_8).toCharArray()) {
                        take(c);
                    }
                }
            }
        } catch (IOException closed) {
            // the child is gone: what was read is kept
        }
    }

    private void take(char c) {
        if (done) {
            return;
        }
        if (c == '\n' || c == '\r') {
            done = !line.toString().isBlank();
        } else if (!Character.isISOControl(c) && line.length() < MAX) {
            line.append(c);
        }
    }

    /** The first non-blank line, once the stream ended (waits at most a second for that); "" if none. */
    String get() {
        try {
            reader.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (this) {
            return line.toString().strip();
        }
    }
}
