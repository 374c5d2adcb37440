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
 * all round at full speed does (several cushions). The planner's game plan (budget 20,000) before
 * the dense first-shot sweep played it in more strokes.
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

    @Test
    void aShieldedHole() throws Exception {
        int[] codes = Tracks.framed();
        // The hole at tile (44, 12) behind a shield across its west side, open north and south.
        wall(codes, 40, 6, 40, 18);
        Playthrough.Result r = play(codes);
        System.out.println("shield: " + r.holed() + " " + r.strokes() + " " + r.simulations());
    }

    @Test
    void aPocket() throws Exception {
        int[] codes = Tracks.framed();
        // The hole in a pocket open to the north only.
        wall(codes, 40, 6, 40, 18);
        wall(codes, 40, 18, 47, 18);
        Playthrough.Result r = play(codes);
        System.out.println("pocket: " + r.holed() + " " + r.strokes() + " " + r.simulations());
    }

    @Test
    void aZigzag() throws Exception {
        int[] codes = Tracks.framed();
        wall(codes, 20, 1, 20, 17);
        wall(codes, 32, 7, 32, 23);
        Playthrough.Result r = play(codes);
        System.out.println("zigzag: " + r.holed() + " " + r.strokes() + " " + r.simulations());
    }

    @Test
    void aStartRoom() throws Exception {
        int[] codes = Tracks.framed();
        // The start in a room open to the west (away from the hole).
        wall(codes, 2, 8, 8, 8);
        wall(codes, 2, 16, 8, 16);
        wall(codes, 8, 8, 8, 16);
        Playthrough.Result r = play(codes);
        System.out.println("room: " + r.holed() + " " + r.strokes() + " " + r.simulations());
    }
}
