package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Two strokes through a field of pillars: no ace from the start, and from the lay-ups the straight
 * look-ahead tries no straight putt either, but from some a shot off the pillars holes out. The
 * planner's quick plan (budget 20,000) took 3 strokes on both courses before it looked ahead with
 * a sweep all round from its sweep's best rest points (AceLayup); on 16 such lattices 53 strokes
 * before, 48 after, none worse.
 */
class ClassicAceLayupTest {

    /** Blocks of 3x3 tiles every {@code px} tiles along rows 4 tiles apart, every other row shifted by half. */
    static int[] pillars(int px, int x0, int y0) {
        int[] codes = Tracks.framed();
        for (int row = 0; y0 + 4 * row < TileMap.HEIGHT - 1; row++) {
            int y = y0 + 4 * row;
            for (int x = x0 + (row % 2) * (px / 2); x < TileMap.WIDTH - 1; x += px) {
                if (covers(x, y, 4, 12) || covers(x, y, 44, 12)) continue;
                ClassicAceTest.wall(codes, x, y, Math.min(TileMap.WIDTH - 2, x + 2), Math.min(TileMap.HEIGHT - 2, y + 2));
            }
        }
        return codes;
    }

    private static boolean covers(int x, int y, int tx, int ty) {
        return tx >= x && tx <= x + 2 && ty >= y && ty <= y + 2;
    }

    @Test
    void pillarsSevenApartInTwo() throws Exception {
        assertTwoStrokes(pillars(7, 1, 3));
    }

    @Test
    void pillarsEightApartInTwo() throws Exception {
        assertTwoStrokes(pillars(8, 5, 2));
    }

    private static void assertTwoStrokes(int[] codes) throws Exception {
        World world = World.of(TrackConverterTest.convert(codes).course());
        Playthrough.Result r = ClassicAceTest.play(codes);
        assertTrue(r.holed() && r.strokes() == 2, r.strokes() + " strokes, holed " + r.holed());
        // Replayed from the start: the lay-up rests where the second shot holes out.
        Simulator sim = new Simulator(world, SimulationSettings.DEFAULT);
        var layup = r.shots().get(0).shot();
        ShotResult first = sim.simulate(world.course().start().x(), world.course().start().y(), layup.vx(), layup.vy());
        assertEquals(Outcome.STOPPED, first.outcome());
        var putt = r.shots().get(1).shot();
        assertEquals(Outcome.HOLED, sim.simulate(first.endX(), first.endY(), putt.vx(), putt.vy()).outcome());
    }
}
