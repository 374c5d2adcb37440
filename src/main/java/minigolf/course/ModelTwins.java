package minigolf.course;

import java.nio.file.Path;
import minigolf.mesh.TriangleMesh;

/**
 * A model's lighter twin for the software quality tier: {@code NAME.low.obj} beside {@code NAME.obj}
 * (looked for as the model itself is: the course's folder, then the bundled models). It is drawn
 * only; the physics always keeps the full model, so a twin must have the same shape and the same
 * materials with fewer triangles (tools/generate_windmill.py writes the windmill's).
 */
public final class ModelTwins {
    private ModelTwins() {
    }

    /** The twin's file name for a model file ("models/windmill.obj" gives "models/windmill.low.obj"), or null if it does not end in .obj. */
    public static String lowName(String file) {
        if (file == null || file.length() <= 4 || !file.regionMatches(true, file.length() - 4, ".obj", 0, 4)) return null;
        return file.substring(0, file.length() - 4) + ".low" + file.substring(file.length() - 4);
    }

    /**
     * The twin of {@code file} from {@code courseFolder} (null: the bundled models only), or null when
     * there is none or it cannot be read (the full model is drawn then).
     */
    public static TriangleMesh low(String file, Path courseFolder) {
        String name = lowName(file);
        if (name == null) return null;
        try {
            return ModelFiles.in(courseFolder).load(name);
        } catch (ModelFiles.ModelException e) {
            return null;
        }
    }
}
