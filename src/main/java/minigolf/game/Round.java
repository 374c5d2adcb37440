package minigolf.game;

import java.util.List;
import minigolf.course.Limits;
import minigolf.physics.World;

/**
 * A round of minigolf: a name and its holes in playing order, each a course with its par. Loaded
 * by {@link RoundLoader} from a round file (docs/course-format.md, "Round files"); every hole's
 * course is loaded and checked when the round is.
 *
 * @param source where the round came from (a file, a save game), for messages
 */
public record Round(String name, List<Hole> holes, String source) {
    /** Most holes in a round (36: two 18-hole courses back to back). */
    public static final int MAX_HOLES = 36;
    /** Highest par a hole may have (a stroke limit of 10 would pick up before par 10 means anything). */
    public static final int MAX_PAR = 9;

    /**
     * One hole: the course file as the round file names it, its par and the loaded course.
     *
     * @param course the path as written in the round file (relative to the round file's folder)
     */
    public record Hole(String course, int par, World world) {
        public Hole {
            if (course == null || course.isBlank()) throw new IllegalArgumentException("a hole needs a course file");
            String longName = Limits.tooLong(course, Limits.FILE_NAME_CHARS);
            if (longName != null) throw new IllegalArgumentException("the course file name is " + longName);
            if (par < 1 || par > MAX_PAR) throw new IllegalArgumentException("par must be 1 to " + MAX_PAR + ", got " + par);
            if (world == null) throw new IllegalArgumentException("a hole needs its loaded course");
        }
    }

    public Round {
        if (name == null || name.isBlank()) throw new IllegalArgumentException("a round needs a name");
        String longName = Limits.tooLong(name, Limits.NAME_CHARS);
        if (longName != null) throw new IllegalArgumentException("the round's name is " + longName);
        holes = List.copyOf(holes);
        if (holes.isEmpty() || holes.size() > MAX_HOLES) {
            throw new IllegalArgumentException("a round has 1 to " + MAX_HOLES + " holes, got " + holes.size());
        }
    }

    /** The sum of the holes' pars. */
    public int par() {
        return holes.stream().mapToInt(Hole::par).sum();
    }

    public int size() {
        return holes.size();
    }

    public Hole hole(int index) {
        return holes.get(index);
    }
}
