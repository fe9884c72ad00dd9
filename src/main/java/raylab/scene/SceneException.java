package raylab.scene;

/**
 * A scene file that cannot be used, with where and why, as one line:
 * {@code scenes/bad.json:12:5: $.surfaces[2].radius: radius must be positive, got -1}.
 */
public class SceneException extends Exception {
    private static final long serialVersionUID = 1L;

    /** The message is kept to one line: control characters in it are escaped ({@link Display}). */
    public SceneException(String oneLine) {
        super(Display.escape(oneLine));
    }

    public SceneException(String oneLine, Throwable cause) {
        super(Display.escape(oneLine), cause);
    }
}
