package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The planner on a track of our own with the classic tracks' water: a pool drawn as a hazard zone on
 * flat ground. When the bots' maps did not see such water, the planner took the hole behind the pool
 * for two metres away and played to the bank again and again (as on the sample's Dante-M-balls).
 */
class ClassicPlannerTest {
    @Test
    void thePlannerGoesRoundABayToTheHoleInIt() throws Exception {
        int[] codes = Tracks.framed();
        // The hole two metres east of the start, in a bay of water open only to the east: the way in
        // goes round the bay, 15 m, most of it away from the hole.
        Tracks.set(codes, 44, 12, TileMap.GRASS);
        Tracks.set(codes, 12, 12, TileMap.specialTile(1, PixelMap.GRASS));
        int water = TileMap.elementTile(0, PixelMap.WATER, PixelMap.WATER);
        for (int y = 3; y <= 21; y++) {
            for (int x = 8; x <= 9; x++) Tracks.set(codes, x, y, water);
        }
        for (int x = 8; x <= 30; x++) {
            for (int y : new int[] {3, 4, 20, 21}) Tracks.set(codes, x, y, water);
        }
        World world = World.of(TrackConverterTest.convert(codes).course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed(), "not holed in 10 strokes: " + r.strokes() + " strokes, " + r.simulations() + " simulations");
        assertTrue(r.strokes() <= 6, "strokes: " + r.strokes());
    }
}
