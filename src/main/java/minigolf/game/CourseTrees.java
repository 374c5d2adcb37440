package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.Collections;
import java.util.Map;
import java.util.WeakHashMap;
import minigolf.course.CourseWriter;
import minigolf.physics.World;

/**
 * Each world's course as the JSON tree saves embed, written once per world: a round's start save
 * holds its nine or eighteen courses (about 110 KB for Meadowbrook's front nine), and writing and
 * re-reading them took 4-12 ms of CPU at every online room's start, on the rooms' shared threads,
 * where other rooms' strokes waited behind it (docs/online.md, "Benchmarks"). Worlds are immutable;
 * the trees are only ever written out, never changed; a world no longer used drops its tree.
 */
final class CourseTrees {
    private static final Map<World, JsonNode> TREES = Collections.synchronizedMap(new WeakHashMap<>());

    private CourseTrees() {
    }

    /** The course of {@code world} as a JSON tree (shared: callers must not change it). */
    static JsonNode of(World world) throws IOException {
        JsonNode tree = TREES.get(world);
        if (tree == null) {
            tree = JsonFields.MAPPER.readTree(CourseWriter.toJson(world.course()));
            TREES.put(world, tree);
        }
        return tree;
    }
}
