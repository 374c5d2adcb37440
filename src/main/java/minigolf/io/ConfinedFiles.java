package minigolf.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;

/**
 * Names of files that a shared file refers to, resolved so that it cannot read other files of the
 * machine: a course's models (and their material libraries) only inside the course's folder; a
 * round's holes in its folder and the folders beside it (the bundled rounds' {@code ../holes/...}),
 * never above the folder that holds them. Absolute names and links that lead out are refused too.
 * Messages name the path as written and quote nothing of any file.
 */
public final class ConfinedFiles {
    private static final String COURSE_RULE = "a course may only use files in its own folder or the bundled models";
    private static final String ROUND_RULE = "a round names its courses relative to its own file, e.g. ../holes/01-first-tee.json";

    private ConfinedFiles() {
    }

    /**
     * The normalised relative name ({@code models/windmill.obj}), with {@code \} read as {@code /}.
     *
     * @throws TextFiles.TextFileException for absolute names and names that leave the folder
     */
    public static Path relativeName(String name) throws TextFiles.TextFileException {
        Path normal = notAbsolute(name, "the course's folder", COURSE_RULE).normalize();
        if (normal.startsWith("..") || normal.toString().isEmpty()) throw leaves("the course's folder", COURSE_RULE);
        return normal;
    }

    /**
     * The real path of {@code name} inside {@code folder}, or null when nothing is there (the caller
     * may then look among bundled files).
     *
     * @throws TextFiles.TextFileException for names refused by {@link #relativeName} and links out of the folder
     */
    public static Path resolve(Path folder, String name) throws TextFiles.TextFileException {
        relativeName(name);
        Path path = within(folder, folder, name, "the course's folder", COURSE_RULE);
        if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) return null;
        try {
            return path.toRealPath();
        } catch (IOException | RuntimeException e) {
            throw new TextFiles.TextFileException("cannot read: a broken link or an unreadable folder");
        }
    }

    /**
     * The path of a round's hole course {@code name} (as written in the round file in {@code roundFolder}):
     * in that folder or a folder beside it, i.e. never outside the folder's parent, the collection
     * the round was installed with ({@code courses/} for {@code courses/rounds/}). The path may not
     * exist (the course reader then says so).
     *
     * @throws TextFiles.TextFileException for absolute names, names above the collection and links out of it
     */
    public static Path roundCourse(Path roundFolder, String name) throws TextFiles.TextFileException {
        Path folder = roundFolder.toAbsolutePath().normalize();
        Path collection = folder.getParent() != null ? folder.getParent() : folder;
        return within(collection, folder, name, "the round's folder and the folders beside it", ROUND_RULE);
    }

    /** {@code name} resolved in {@code folder}, refused unless it and (through links) its real path lie inside {@code root}. */
    private static Path within(Path root, Path folder, String name, String where, String rule) throws TextFiles.TextFileException {
        Path relative = notAbsolute(name, where, rule);
        Path top = root.toAbsolutePath().normalize();
        Path path = folder.toAbsolutePath().normalize().resolve(relative).normalize();
        if (!path.startsWith(top) || path.equals(top)) throw leaves(where, rule);
        if (!Files.exists(path, LinkOption.NOFOLLOW_LINKS)) return path;
        try {
            if (!path.toRealPath().startsWith(top.toRealPath())) {
                throw new TextFiles.TextFileException("refused: a link that leads out of " + where);
            }
        } catch (TextFiles.TextFileException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new TextFiles.TextFileException("cannot read: a broken link or an unreadable folder");
        }
        return path;
    }

    private static Path notAbsolute(String name, String where, String rule) throws TextFiles.TextFileException {
        String n = name.replace('\\', '/');
        Path relative;
        try {
            relative = Path.of(n);
        } catch (InvalidPathException e) {
            throw new TextFiles.TextFileException("refused: not a valid file name");
        }
        if (relative.isAbsolute() || n.startsWith("/") || n.matches("^[A-Za-z]:.*")) {
            throw new TextFiles.TextFileException("refused: an absolute path (" + rule + ")");
        }
        return relative;
    }

    private static TextFiles.TextFileException leaves(String where, String rule) {
        return new TextFiles.TextFileException("refused: the path leaves " + where + " (" + rule + ")");
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
