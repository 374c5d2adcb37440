package minigolf.course;

import minigolf.mesh.ObjParser;

/**
 * The most any file may ask for, checked before the work is done, so that every accepted course,
 * model, saved game and settings file loads in well under 2 s and 1 GB (the worst cases are timed
 * by {@code minigolf bench-limits}; docs/course-format.md lists the limits). Each check fails with
 * one line naming the file, the field and the limit.
 */
public final class Limits {
    /** A course file (a 512 x 512 grid with both friction grids is about 4 MB). */
    public static final long COURSE_FILE_BYTES = 8L << 20;
    /** One .obj model file. */
    public static final long MODEL_FILE_BYTES = 8L << 20;
    /** A saved game, which embeds its course. */
    public static final long SAVE_FILE_BYTES = COURSE_FILE_BYTES + (1L << 20);
    /** A round file (a name and up to 36 holes' file names and pars: a few kilobytes). */
    public static final long ROUND_FILE_BYTES = 1L << 20;
    /** A saved round, which embeds the courses of all its holes (up to 18 small holes fit easily). */
    public static final long ROUND_SAVE_FILE_BYTES = 24L << 20;
    /** The high-score table (ten scores per round and each player's bests). */
    public static final long SCORES_FILE_BYTES = 1L << 20;
    /** The settings file (and the volumes file beside it). */
    public static final long SETTINGS_FILE_BYTES = 64L << 10;
    /** Nesting of JSON arrays and objects (a course needs 5 levels). */
    public static final int JSON_DEPTH = 32;
    /** Nodes of a height grid (512 x 512). */
    public static final int GRID_NODES = 1 << 18;
    /** Obstacles of one course. */
    public static final int OBSTACLES = 2_500;
    /** Friction zones of one course. */
    public static final int ZONES = 500;
    /** Points of one polygon zone. */
    public static final int POLYGON_POINTS = 1_000;
    /** Points of all polygon zones together (the friction lookup visits them on every step). */
    public static final int ALL_POLYGON_POINTS = 10_000;
    /** Push zones of one course (their pushes are looked up on every step, as the friction zones). */
    public static final int PUSH_ZONES = 500;
    /** Magnets of one course. */
    public static final int MAGNETS = 100;
    /** Teleports of one course. */
    public static final int TELEPORTS = 100;
    /** Exits of one teleport. */
    public static final int TELEPORT_EXITS = 16;
    /** Holes beside the main one (a classic track has up to ten; each is checked on every step near it). */
    public static final int EXTRA_HOLES = 100;
    /** Breakable bricks of one course (a classic track has at most 1,225 tiles). */
    public static final int BRICKS = 2_500;
    /** Moving obstacles of one course (each is swept separately, in its own frame, on every step near it). */
    public static final int MOVING_OBSTACLES = 64;
    /** Points of one sliding obstacle's path. */
    public static final int PATH_POINTS = 100;
    /** The strongest push or magnet (m/s²): five times gravity. */
    public static final double FORCE = 50;
    /** A motion's shortest period (s): a turn takes at least this long. */
    public static final double SHORTEST_PERIOD = 0.2;
    /** A motion's longest period (s). */
    public static final double LONGEST_PERIOD = 3600;
    /** The fastest a sliding obstacle may move (m/s). */
    public static final double SLIDE_SPEED = 20;
    /** How far a turning or swinging obstacle's body may reach from its pivot (m), so its edge moves at most ~300 m/s. */
    public static final double MOTION_REACH = 10;
    /** Cells of one cells shape (a classic track's 735 x 375 pixels is 275,625). */
    public static final int CELLS = 1 << 20;
    /** Row spans of one cells shape. */
    public static final int CELL_SPANS = 200_000;
    /** Vertices (v lines) of one .obj model. */
    public static final int MODEL_VERTICES = ObjParser.MAX_VERTICES;
    /** Triangles of one .obj model (after polygons are split). */
    public static final int MODEL_TRIANGLES = ObjParser.MAX_TRIANGLES;
    /** Model triangles of all model obstacles together, a model placed twice counted twice. */
    public static final int TRIANGLES = 200_000;
    /** The terrain's height (sampled over the bounds) stays within +-this many metres. */
    public static final double HEIGHT = 1_000;
    /**
     * Characters of a name that a file puts on screen (a course's, a round's, a round's in a save or
     * in the score table); the editor's name field holds as many. Player names have their own, shorter limit.
     */
    public static final int NAME_CHARS = 128;
    /** Characters of a file name written inside a file (a model, a round's hole course, a saved round's source). */
    public static final int FILE_NAME_CHARS = 1_024;

    /** "too long: N characters (the limit is L)", or null when {@code text} has at most {@code limit} characters. */
    public static String tooLong(String text, int limit) {
        return text.length() <= limit ? null : "too long: " + text.length() + " characters (the limit is " + limit + ")";
    }

    private Limits() {
    }
}
