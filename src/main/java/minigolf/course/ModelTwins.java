package minigolf.course;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
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

    /**
     * The twins of one course folder's models, each file looked for once (the editor rebuilds the
     * drawn obstacles on every change; reading the .obj files each time would stall it).
     */
    public static final class Cache {
        private final Path courseFolder;
        /** By model file: its twin, or empty when it has none. */
        private final Map<String, Optional<TriangleMesh>> found = new HashMap<>();

        /** Twins from {@code courseFolder} (null: the bundled models only). */
        public Cache(Path courseFolder) {
            this.courseFolder = courseFolder;
        }

        /**
         * The obstacles to draw: each model with a twin becomes the same model (file, place,
         * rotation, scale, restitution) with the twin's mesh; everything else is passed on as it is.
         */
        public List<Obstacle> drawn(List<Obstacle> list) {
            List<Obstacle> out = new ArrayList<>(list.size());
            for (Obstacle o : list) {
                if (o instanceof Obstacle.Model m) {
                    TriangleMesh twin = found.computeIfAbsent(m.file(), f -> Optional.ofNullable(low(f, courseFolder))).orElse(null);
                    if (twin != null) o = new Obstacle.Model(m.file(), m.position(), m.rotationDeg(), m.scale(), m.restitution(), twin);
                }
                out.add(o);
            }
            return out;
        }

        /** Model files looked for so far (tests). */
        int filesLookedFor() {
            return found.size();
        }
    }
}
