package minigolf.bot.map;

import minigolf.bot.CancellationToken;
import minigolf.physics.World;

/**
 * The grid and the distance field to the hole of one world, built on first use and kept while a
 * bot plays that world (they depend on the course only, not on the ball).
 */
public final class CourseMaps {
    /** Whether the distance field weighs each metre by the ground's friction (see {@link DistanceField}). */
    private final boolean frictionAware;
    private World world;
    private CourseGrid grid;
    private DistanceField toHole;

    public CourseMaps() {
        this(false);
    }

    public CourseMaps(boolean frictionAware) {
        this.frictionAware = frictionAware;
    }

    public void prepare(World w, CancellationToken token) {
        if (w == world) return;
        grid = CourseGrid.of(w, token);
        toHole = new DistanceField(grid, w.hole().position().x(), w.hole().position().y(), token, frictionAware);
        world = w;
    }

    public CourseGrid grid() {
        return grid;
    }

    public DistanceField toHole() {
        return toHole;
    }
}
