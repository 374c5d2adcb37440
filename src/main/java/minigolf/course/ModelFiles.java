package minigolf.course;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Map;
import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;

/**
 * Where the .obj files of {@code model} obstacles come from: a file name is resolved against the
 * course file's folder first, then the game's resources ({@code /<file>}, then
 * {@code /courses/<file>} on the classpath, where the shipped courses live).
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

    /** Files beside the course file {@code courseFile}, then the classpath. */
    static ModelFiles beside(Path courseFile) {
        Path folder = courseFile.toAbsolutePath().getParent();
        return file -> read(folder, file);
    }

    /** As {@link #beside(Path)} when the source name is a path; else the working directory, then the classpath. */
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

    /** The meshes a course already holds, by file name (to check a course before saving it elsewhere). */
    static ModelFiles known(Map<String, TriangleMesh> meshes, ModelFiles fallback) {
        return file -> {
            TriangleMesh mesh = meshes.get(file);
            return mesh != null ? mesh : fallback.load(file);
        };
    }

    private static TriangleMesh read(Path folder, String file) throws ModelException {
        Path path;
        try {
            path = folder.resolve(file);
        } catch (InvalidPathException e) {
            throw new ModelException("not a valid file name: " + CourseException.oneLine(file));
        }
        if (Files.isRegularFile(path)) {
            try (InputStream in = Files.newInputStream(path)) {
                return parse(file, in);
            } catch (IOException e) {
                throw new ModelException(file + ": cannot read: " + CourseLoader.describe(e, path));
            }
        }
        String name = file.replace('\\', '/');
        for (String resource : new String[] {"/" + name, "/courses/" + name}) {
            InputStream in = ModelFiles.class.getResourceAsStream(resource.replace("//", "/"));
            if (in == null) continue;
            try (in) {
                return parse(file, in);
            } catch (IOException e) {
                throw new ModelException(file + ": cannot read: " + e.getMessage());
            }
        }
        throw new ModelException("no such file: " + file + " (looked in " + folder + " and the game's resources)");
    }

    private static TriangleMesh parse(String file, InputStream in) throws ModelException {
        try {
            return ObjParser.parse(in);
        } catch (ObjException e) {
            throw new ModelException(file + ": " + e.getMessage());
        }
    }
}
