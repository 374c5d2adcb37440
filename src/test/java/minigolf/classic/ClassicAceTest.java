package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Aces the best players of the classic game found: the hole hidden from the start so that neither
 * the straight line, nor a single cushion, nor the shots round the shortest path hole, but a shot
 * all round at full speed does (several cushions). The planner's quick plan (budget 20,000) took 2
 * strokes on each before it swept all round (DenseSweep) to a capture hole.
 */
class ClassicAceTest {
    static final int BLOCK = TileMap.elementTile(0, PixelMap.BLOCK, PixelMap.BLOCK);

    static void wall(int[] codes, int x0, int y0, int x1, int y1) {
        for (int x = x0; x <= x1; x++) {
            for (int y = y0; y <= y1; y++) Tracks.set(codes, x, y, BLOCK);
        }
    }

    static Playthrough.Result play(int[] codes) throws Exception {
        World world = World.of(TrackConverterTest.convert(codes).course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        return r;
    }

    /**
     * The hole walled in all round: no way along the ground. The original game had no chips, so
     * neither do imported tracks (physics.puttsOnly): before, the planner chipped over the wall
     * (on 83 of the 177 sample tracks it played 242 chips).
     */
    @Test
    void aWalledInHoleCannotBeChippedInto() throws Exception {
        int[] codes = Tracks.framed();
        wall(codes, 41, 9, 47, 9);
        wall(codes, 41, 15, 47, 15);
        wall(codes, 41, 9, 41, 15);
        TrackConverter.Converted converted = TrackConverterTest.convert(codes);
        assertTrue(converted.course().physics().puttsOnly());
        World world = World.of(converted.course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 2, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertFalse(r.holed(), r.strokes() + " strokes");
        for (Playthrough.PlayedShot p : r.shots()) assertEquals(0, p.shot().vz(), p.shot().toString());
    }

    /** The hole at tile (44, 12) behind a shield across its west side: open north and south. */
    @Test
    void aShieldedHoleIsAcedOffTheCushions() throws Exception {
        int[] codes = Tracks.framed();
        wall(codes, 40, 6, 40, 18);
        assertAced(codes);
    }

    /** The same with the south closed: a pocket open to the north only. */
    @Test
    void aHoleInAPocketIsAcedOffTheCushions() throws Exception {
        int[] codes = Tracks.framed();
        wall(codes, 40, 6, 40, 18);
        wall(codes, 40, 18, 47, 18);
        assertAced(codes);
    }

    private static void assertAced(int[] codes) throws Exception {
        World world = World.of(TrackConverterTest.convert(codes).course());
        Playthrough.Result r = play(codes);
        assertTrue(r.holed() && r.strokes() == 1, r.strokes() + " strokes, holed " + r.holed());
        var ace = r.shots().get(0).shot();
        assertEquals(Outcome.HOLED, new Simulator(world, SimulationSettings.DEFAULT)
                .simulate(world.course().start().x(), world.course().start().y(), ace.vx(), ace.vy()).outcome());
    }
}
