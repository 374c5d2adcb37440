package minigolf.editor;

import java.io.IOException;
import java.io.InputStream;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;

/**
 * The .obj models the object tool can place: the ones bundled with the game. Each is named by the
 * {@code file} string the course keeps, and read from the classpath exactly where the course loader
 * looks when the file is not beside the course ({@code /<file>}, then {@code /courses/<file>}), so a
 * course saved anywhere loads them back.
 */
public final class ModelCatalog {
    /** The bundled models, by the file string a course writes (courses/models/ and src/main/resources/models/). */
    public static final List<String> BUNDLED = List.of("models/windmill.obj", "models/tree-crown.obj",
            "models/windmill-blades.obj");

    private static final Map<String, TriangleMesh> CACHE = new ConcurrentHashMap<>();

    private ModelCatalog() {
    }

    /**
     * The mesh of a bundled model (parsed once).
     *
     * @throws IllegalArgumentException naming the file when it is not in the game's resources or is malformed
     */
    public static TriangleMesh load(String file) {
        TriangleMesh cached = CACHE.get(file);
        if (cached != null) return cached;
        String name = file.replace('\\', '/');
        for (String resource : new String[]{"/" + name, "/courses/" + name}) {
            InputStream in = ModelCatalog.class.getResourceAsStream(resource.replace("//", "/"));
            if (in == null) continue;
            try (in) {
                TriangleMesh mesh = ObjParser.parse(in);
                CACHE.put(file, mesh);
                return mesh;
            } catch (ObjException e) {
                throw new IllegalArgumentException(file + ": " + e.getMessage());
            } catch (IOException e) {
                throw new IllegalArgumentException(file + ": cannot read: " + e.getMessage());
            }
        }
        throw new IllegalArgumentException("no such model in the game's resources: " + file);
    }
}
