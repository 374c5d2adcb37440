package minigolf.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;

/**
 * Names of files that a course refers to (models, their material libraries) resolved so that a
 * shared course cannot read other files of the machine: only relative names that stay inside the
 * course's folder; links must lead to a place inside it too. Messages name the path as written and
 * quote nothing of any file.
 */
public final class ConfinedFiles {
    private ConfinedFiles() {
    }

    /**
     * The normalised relative name ({@code models/windmill.obj}), with {@code \} read as {@code /}.
     *
     * @throws TextFiles.TextFileException for absolute names and names that leave the folder
     */
    public static Path relativeName(String name) throws TextFiles.TextFileException {
        String n = name.replace('\\', '/');
        Path relative;
        try {
            relative = Path.of(n);
        } catch (InvalidPathException e) {
            throw new TextFiles.TextFileException("refused: not a valid file name");
        }
        if (relative.isAbsolute() || n.startsWith("/") || n.matches("^[A-Za-z]:.*")) {
            throw new TextFiles.TextFileException("refused: an absolute path (a course may only use files in its own"
                    + " folder or the bundled models)");
        }
        Path normal = relative.normalize();
        if (normal.startsWith("..") || normal.toString().isEmpty()) {
            throw new TextFiles.TextFileException("refused: the path leaves the course's folder (a course may only use"
                    + " files in its own folder or the bundled models)");
        }
        return normal;
    }

    /**
     * The real path of {@code name} inside {@code folder}, or null when nothing is there (the caller
     * may then look among bundled files).
     *
     * @throws TextFiles.TextFileException for names refused by {@link #relativeName} and links out of the folder
     */
    public static Path resolve(Path folder, String name) throws TextFiles.TextFileException {
        Path base = folder.toAbsolutePath().normalize();
        Path path = base.resolve(relativeName(name));
        if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) return null;
        try {
            Path real = path.toRealPath();
            if (!real.startsWith(base.toRealPath())) {
                throw new TextFiles.TextFileException("refused: a link that leads out of the course's folder");
            }
            return real;
        } catch (TextFiles.TextFileException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new TextFiles.TextFileException("cannot read: a broken link or an unreadable folder");
        }
    }

    /**
     * Where a bundled file may lie on the classpath: {@code /courses/<name>} (the shipped courses and
     * their models) and, for {@code models/...}, {@code /models/...} (the game's own models); nowhere
     * else in the jar.
     */
    public static java.util.List<String> bundledResources(Path relativeName) {
        String n = relativeName.toString().replace('\\', '/');
        return n.startsWith("models/") ? java.util.List.of("/courses/" + n, "/" + n) : java.util.List.of("/courses/" + n);
    }
}
