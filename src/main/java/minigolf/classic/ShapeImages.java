package minigolf.classic;

import java.io.IOException;
import java.nio.file.FileVisitOption;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * Finds the original game's {@code shapes.gif} and {@code special.gif} near a tracks folder, as a
 * checkout of a reimplementation keeps them (the tracks in its server's resources, the images in
 * its client's): the folder and its ancestors, up to {@link #ANCESTORS} levels, each searched
 * {@link #DEPTH} levels deep, at most {@link #MAX_VISITS} entries in all.
 */
public final class ShapeImages {
    static final int ANCESTORS = 6;
    static final int DEPTH = 7;
    static final int MAX_VISITS = 50_000;

    private ShapeImages() {
    }

    /** The folder holding both images, if one is found. */
    public static Optional<Path> locate(Path tracks) {
        Path dir = tracks.toAbsolutePath().normalize();
        int[] visits = {0};
        for (int level = 0; level <= ANCESTORS && dir != null && dir.getParent() != null; level++, dir = dir.getParent()) {
            Optional<Path> found = search(dir, visits);
            if (found.isPresent()) return found;
            if (visits[0] >= MAX_VISITS) break;
        }
        return Optional.empty();
    }

    private static Optional<Path> search(Path root, int[] visits) {
        if (hasBoth(root)) return Optional.of(root);
        try (Stream<Path> walk = Files.walk(root, DEPTH, new FileVisitOption[0])) {
            return walk.takeWhile(p -> visits[0]++ < MAX_VISITS)
                    .filter(p -> p.getFileName() != null && p.getFileName().toString().equals("shapes.gif"))
                    .map(Path::getParent)
                    .filter(ShapeImages::hasBoth)
                    .findFirst();
        } catch (IOException | RuntimeException e) {
            return Optional.empty(); // an unreadable folder holds no images we can use
        }
    }

    private static boolean hasBoth(Path dir) {
        return dir != null && Files.isRegularFile(dir.resolve("shapes.gif")) && Files.isRegularFile(dir.resolve("special.gif"));
    }
}
