package minigolf.bot.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.course.CourseException;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The friction-aware distance field on dirt (μk 0.8) with a winding grass path (μk 0.1): its route
 * from the start follows the grass, where the plain field cuts straight across the dirt.
 */
class FrictionAwareFieldTest {
    /** 10 x 6 m of dirt; grass up from the start, along the top and down to the hole (a U, 15 m). */
    static World dirtWithGrassPath() {
        String json = """
                {"format": 1, "name": "dirt with a grass path", "terrain": {"height": "0"},
                 "bounds": {"min": [0, 0], "max": [10, 6]},
                 "physics": {"gravity": 9.81, "kineticFriction": 0.8, "staticFriction": 0.9, "maxSpeed": 5, "model": "classic"},
                 "start": [1, 1], "hole": {"position": [9, 1], "radius": 0.1, "rule": "rest"},
                 "zones": [
                   {"shape": {"type": "rect", "min": [0.4, 0.4], "max": [1.6, 5.6]}, "kineticFriction": 0.1, "staticFriction": 0.2},
                   {"shape": {"type": "rect", "min": [0.4, 4.4], "max": [9.6, 5.6]}, "kineticFriction": 0.1, "staticFriction": 0.2},
                   {"shape": {"type": "rect", "min": [8.4, 0.4], "max": [9.6, 5.6]}, "kineticFriction": 0.1, "staticFriction": 0.2}
                 ],
                 "obstacles": []}
                """;
        try {
            return World.parse(json, "dirt-grass");
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    @Test
    void theRouteFollowsTheGrassPath() {
        World w = dirtWithGrassPath();
        CourseGrid grid = CourseGrid.of(w, CancellationToken.none());
        DistanceField aware = new DistanceField(grid, 9, 1, CancellationToken.none(), true);
        List<double[]> path = aware.path(1, 1);
        int onDirt = 0;
        double topmost = 0;
        for (double[] p : path) {
            if (w.friction().kinetic(p[0], p[1]) > 0.5) onDirt++;
            topmost = Math.max(topmost, p[1]);
        }
        assertEquals(0, onDirt, "every point of the route on the grass");
        assertTrue(topmost > 4.4, "up to the top leg: " + topmost);
        // In metres of grass: the U (up 4 m, along 8, down 4, its corners cut inside the 1.2 m path), far less
        // than the 8 m of dirt straight across (64).
        double d = aware.at(1, 1);
        assertTrue(d > 13 && d < 17, "grass route " + d);
    }

    private static int strokes(boolean aces, boolean frictionAware) {
        // No time limit: the game depends on the budget alone (SearchBounds), however loaded the machine.
        Playthrough.Result r = Playthrough.play(new PlannerBot(aces, frictionAware), dirtWithGrassPath(),
                SimulationSettings.DEFAULT, 20, 20_000, 1, CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed());
        return r.strokes();
    }

    @Test
    void thePlannerPlaysAlongTheGrassInsteadOfOntoTheDirtAndBack() {
        // The failure: the plain field sends the ball straight at the hole onto the dirt, where it
        // stops after a metre or two, and back (13 strokes). Along the grass: 4; planner-aces 3 (9 plain).
        assertEquals(13, strokes(false, false));
        assertEquals(4, strokes(false, true));
        assertEquals(9, strokes(true, false));
        assertEquals(3, strokes(true, true));
    }

    @Test
    void thePlainFieldCutsAcrossTheDirt() {
        World w = dirtWithGrassPath();
        CourseGrid grid = CourseGrid.of(w, CancellationToken.none());
        DistanceField plain = new DistanceField(grid, 9, 1, CancellationToken.none());
        double topmost = 0;
        for (double[] p : plain.path(1, 1)) topmost = Math.max(topmost, p[1]);
        assertTrue(topmost < 1.5, "straight across: " + topmost);
        assertEquals(8, plain.at(1, 1), 0.1);
    }

    @Test
    void onAOneFrictionCourseTheFieldIsUnchanged() {
        World w;
        try {
            w = World.load(java.nio.file.Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench/maze-b.json"));
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
        CourseGrid grid = CourseGrid.of(w, CancellationToken.none());
        double hx = w.hole().position().x(), hy = w.hole().position().y();
        DistanceField plain = new DistanceField(grid, hx, hy, CancellationToken.none());
        DistanceField aware = new DistanceField(grid, hx, hy, CancellationToken.none(), true);
        for (int i = 0; i < grid.cols() * grid.rows(); i += 7) {
            assertEquals(plain.cellDistance(i), aware.cellDistance(i), 0.0, "cell " + i);
        }
    }
}
