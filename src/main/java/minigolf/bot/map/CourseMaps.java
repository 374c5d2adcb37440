package minigolf.bot.map;

import minigolf.bot.CancellationToken;
import minigolf.physics.World;

/**
 * The grid and the distance field to the nearest hole of one world, built on first use and kept while a
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
        var holes = w.holes();
        double[] xs = new double[holes.size()], ys = new double[holes.size()];
        for (int i = 0; i < xs.length; i++) {
            xs[i] = holes.get(i).position().x();
            ys[i] = holes.get(i).position().y();
        }
        toHole = new DistanceField(grid, xs, ys, token, frictionAware);
        world = w;
    }

    public CourseGrid grid() {
        return grid;
    }

    public DistanceField toHole() {
        return toHole;
    }
}
