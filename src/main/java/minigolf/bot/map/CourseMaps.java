package minigolf.bot.map;

import minigolf.bot.CancellationToken;
import minigolf.physics.World;

/**
 * The grid and the distance field to the nearest hole of one world, built on first use and kept while a
 * bot plays that world (they depend on the course and the bricks standing, not on the ball).
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
        // A brick hit but not broken changes the state, not the way: the maps stand.
        if (world != null && w.course() == world.course() && sameBricksStanding(w, world)) {
            world = w;
            return;
        }
        grid = CourseGrid.of(w, token);
        var holes = w.holes();
        double[] xs = new double[holes.size()], ys = new double[holes.size()];
        for (int i = 0; i < xs.length; i++) {
            xs[i] = holes.get(i).position().x();
            ys[i] = holes.get(i).position().y();
        }
        toHole = new DistanceField(grid, xs, ys, token, frictionAware);
        world = w;
    }

    private static boolean sameBricksStanding(World a, World b) {
        for (int i = 0; i < a.state().bricks(); i++) if (a.state().standing(i) != b.state().standing(i)) return false;
        return true;
    }

    public CourseGrid grid() {
        return grid;
    }

    public DistanceField toHole() {
        return toHole;
    }
}
