package minigolf.bot;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;

/**
 * Tool (test scope): writes generated tile courses as course files, so that {@code minigolf
 * experiment --suite DIR} plays them like any suite. Arguments: SEED COUNT DIR. The files are the
 * generator's own JSON, the same courses {@link TileCourses#generate} loads ({@code tile-SEED-I.json}).
 */
final class TileCourseFiles {
    public static void main(String[] args) throws IOException {
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        Path dir = Path.of(args[2]);
        Files.createDirectories(dir);
        for (int i = 0; i < count; i++) {
            Path file = dir.resolve(String.format("tile-%d-%02d.json", seed, i));
            Files.writeString(file, TileCourses.json(seed, i), StandardCharsets.UTF_8);
        }
        System.out.println(count + " courses in " + dir);
    }

    private TileCourseFiles() {
    }
}
