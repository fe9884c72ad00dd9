package raylab.scene;

/**
 * A scene file that cannot be used, with where and why, as one line:
 * {@code scenes/bad.json:12:5: $.surfaces[2].radius: radius must be positive, got -1}.
 */
public class SceneException extends Exception {
    private static final long serialVersionUID = 1L;

    public SceneException(String oneLine) {
        super(oneLine);
    }

    public SceneException(String oneLine, Throwable cause) {
        super(oneLine, cause);
    }
}
