package minigolf.course;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import minigolf.io.ConfinedFiles;
import minigolf.io.TextFiles;
import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;

/**
 * Where the .obj files of {@code model} obstacles come from: a relative file name is resolved in
 * the course file's folder (or its subfolders), then among the game's bundled models (the
 * classpath's {@code /courses/<file>}). A course shared by someone else must not read other files
 * of the machine: absolute names, names that leave the folder with {@code ..}, links that point
 * out of it and anything but regular files are refused with a message that names the path and
 * quotes nothing of any file.
 */
@FunctionalInterface
interface ModelFiles {
    TriangleMesh load(String file) throws ModelException;

    /** A one-line problem with a model file, reported at the obstacle's {@code file} field. */
    final class ModelException extends Exception {
        private static final long serialVersionUID = 1L;

        ModelException(String message) {
            super(message);
        }
    }

    /** Files in the folder of the course file {@code courseFile}, then the bundled models. */
    static ModelFiles beside(Path courseFile) {
        Path folder = courseFile.toAbsolutePath().getParent();
        return file -> read(folder, file);
    }

    /** As {@link #beside(Path)} when the source name is a path; else the working directory, then the bundled models. */
    static ModelFiles besideSource(String sourceName) {
        Path folder;
        try {
            Path parent = sourceName == null ? null : Path.of(sourceName).toAbsolutePath().getParent();
            folder = parent != null ? parent : Path.of("").toAbsolutePath();
        } catch (InvalidPathException e) {
            folder = Path.of("").toAbsolutePath();
        }
        Path base = folder;
        return file -> read(base, file);
    }

    /** Files in {@code folder} (null: none), then the bundled models. */
    static ModelFiles in(Path folder) {
        return file -> read(folder, file);
    }

    /** The meshes a course already holds, by file name (to check a course before saving it elsewhere). */
    static ModelFiles known(Map<String, TriangleMesh> meshes, ModelFiles fallback) {
        return file -> {
            TriangleMesh mesh = meshes.get(file);
            return mesh != null ? mesh : fallback.load(file);
        };
    }

    /** Each file read once per course, however many obstacles place it. */
    static ModelFiles cached(ModelFiles models) {
        Map<String, TriangleMesh> meshes = new HashMap<>();
        return file -> {
            TriangleMesh mesh = meshes.get(file);
            if (mesh == null) {
                mesh = models.load(file);
                meshes.put(file, mesh);
            }
            return mesh;
        };
    }

    private static TriangleMesh read(Path folder, String file) throws ModelException {
        String shown = CourseException.oneLine(file);
        Path base = folder == null ? null : folder.toAbsolutePath().normalize();
        Path relative, real;
        try {
            relative = ConfinedFiles.relativeName(file);
            real = base == null ? null : ConfinedFiles.resolve(base, file);
            if (real != null) return parse(shown, TextFiles.read(real, Limits.MODEL_FILE_BYTES));
        } catch (TextFiles.TextFileException e) {
            String m = e.getMessage();
            throw new ModelException(shown + ": " + (m.startsWith("refused") ? m : "cannot read: " + m));
        }
        // The bundled models: only below /courses and /models on the classpath, never elsewhere in the jar.
        for (String resource : ConfinedFiles.bundledResources(relative)) {
            InputStream in = ModelFiles.class.getResourceAsStream(resource);
            if (in == null) continue;
            try (in) {
                byte[] bytes = in.readNBytes((int) Limits.MODEL_FILE_BYTES + 1);
                if (bytes.length > Limits.MODEL_FILE_BYTES) {
                    throw new ModelException(shown + ": too large (the limit is " + Limits.MODEL_FILE_BYTES + " bytes)");
                }
                return parse(shown, TextFiles.decode(bytes));
            } catch (IOException e) {
                throw new ModelException(shown + ": cannot read: " + e.getMessage());
            }
        }
        throw new ModelException("no such file: " + shown + " (looked in " + (base == null ? "" : base + " and ") + "the game's bundled models)");
    }

    private static TriangleMesh parse(String shown, String text) throws ModelException {
        try {
            return ObjParser.parse(text);
        } catch (ObjException e) {
            throw new ModelException(shown + ": " + e.getMessage());
        }
    }
}
