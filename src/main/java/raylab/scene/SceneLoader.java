package raylab.scene;

import java.nio.file.Path;

/** Reads scene files (JSON, see docs/scene-format.md). */
public final class SceneLoader {
    private SceneLoader() {
    }

    /** Loads and checks a scene; every problem is a SceneException with a one-line message. */
    public static Scene load(Path file) throws SceneException {
        throw new SceneException(file + ": the scene loader is not written yet");
    }
}
