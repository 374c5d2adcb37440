package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.Magnet;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.Simulator;
import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The special blocks of tracks written in the tests (docs/classic-tracks.md, "Special blocks"):
 * downhill tiles push, one-way blocks let the ball through one way, magnets pull and repellers push
 * as deep as the original's, teleports draw their exits. Figures from the original's rules.
 */
class ClassicElementsTest {
    static final ClassicScale SCALE = ClassicScale.standard();
    static final double PX = 0.25 / 15, TICK = 6.5 * PX / 5;
    static final double G = 9.81;

    static void fill(int[] codes, int x0, int x1, int y0, int y1, int element) {
        for (int y = y0; y <= y1; y++) {
            for (int x = x0; x <= x1; x++) Tracks.set(codes, x, y, TileMap.elementTile(0, element, element));
        }
    }

    /** The largest x the ball reaches in a shot. */
    static double furthestX(Simulator s, double x0, double y0, double vx, double vy) {
        double[] max = {x0};
        s.simulate(x0, y0, vx, vy, (TrajectoryListener) (t, x, y, ux, uy) -> max[0] = Math.max(max[0], x));
        return max[0];
    }

    /** The original's downhill push, 0.025 px/tick², is 0.8876 m/s² at 0.25 m a tile; each of the eight directions. */
    @Test
    void downhillTilesArePushZones() throws Exception {
        int[] codes = Tracks.framed();
        for (int d = 0; d < 8; d++) Tracks.set(codes, 10 + 2 * d, 5, TileMap.elementTile(0, PixelMap.DOWNHILL_N + d, PixelMap.GRASS));
        List<PushZone> pushes = TrackConverterTest.convert(codes).course().pushZones();
        assertEquals(8, pushes.size());
        double p = 0.025 * PX / (TICK * TICK);
        assertEquals(0.88757, p, 1e-5);
        double[][] expected = {{0, p}, {p, p}, {p, 0}, {p, -p}, {0, -p}, {-p, -p}, {-p, 0}, {-p, p}};
        for (int d = 0; d < 8; d++) {
            Vec2 push = pushes.get(d).push();
            double k = d % 2 == 1 ? Math.sqrt(0.5) : 1;
            assertEquals(expected[d][0] * k, push.x(), 1e-12, "direction " + d);
            assertEquals(expected[d][1] * k, push.y(), 1e-12, "direction " + d);
            // Exactly the tile's 15 x 15 pixels.
            double cx = (10 + 2 * d + 0.5) * 0.25, cy = (25 - 5.5) * 0.25;
            assertTrue(pushes.get(d).shape().contains(cx, cy));
            assertTrue(!pushes.get(d).shape().contains(cx + 0.13, cy) && !pushes.get(d).shape().contains(cx, cy + 0.13));
        }
    }

    /**
     * A shot east into a field of downhill tiles that push west turns where its speed runs out
     * against friction and push together: v² = v0² − 2 μg·0.375 on the grass before the field
     * (x 1.125 to 1.5 m), then (μg + p) decelerates it.
     */
    @Test
    void aBallRollingAgainstThePushTurnsWhereTheClosedFormSays() throws Exception {
        int[] codes = Tracks.framed();
        fill(codes, 6, 40, 1, 23, PixelMap.DOWNHILL_N + 6); // push west
        Course c = TrackConverterTest.convert(codes).course();
        Simulator s = new Simulator(World.of(c), minigolf.physics.SimulationSettings.DEFAULT);
        double mg = c.physics().kineticFriction() * G, p = SCALE.downhillPush(), v0 = 3;
        double turn = 1.5 + (v0 * v0 - 2 * mg * 0.375) / (2 * (mg + p));
        assertEquals(4.862, turn, 1e-3);
        assertEquals(turn, furthestX(s, c.start().x(), c.start().y(), v0, 0), 1e-3);
    }

    /**
     * One-way blocks (east): a gate on the east face of the column, which a ball going east passes
     * and one coming back west bounces off, keeping 82% of its speed as in the original.
     */
    @Test
    void oneWayBlocksLetTheBallThroughOneWay() throws Exception {
        int[] codes = Tracks.framed();
        fill(codes, 20, 20, 1, 23, PixelMap.ONE_WAY_N + 1);
        Course c = TrackConverterTest.convert(codes).course();
        List<Obstacle.Gate> gates = c.obstacles().stream().filter(o -> o instanceof Obstacle.Gate).map(o -> (Obstacle.Gate) o).toList();
        assertEquals(1, gates.size());
        Obstacle.Gate g = gates.get(0);
        // Pixel column 314's east face, x = 315 px, from the top of row 1 (y = 360 px up) to the bottom of row 23.
        assertEquals(new Vec2(5.25, 6.0), g.from());
        assertEquals(new Vec2(5.25, 0.25), g.to());
        assertEquals(new Vec2(1, 0), g.passNormal());
        assertEquals(0.82, g.restitution());
        Simulator s = new Simulator(World.of(c), minigolf.physics.SimulationSettings.DEFAULT);
        assertEquals(Outcome.HOLED, s.simulate(c.start().x(), c.start().y(), 0.8 * c.physics().maxSpeed(), 0).outcome());
        // From x = 7 m back west at 2 m/s: the ball meets the gate at 5.25 + r with v1 and leaves at 0.82 v1.
        double mg = c.physics().kineticFriction() * G, r = c.physics().ballRadius();
        double[] min = {7};
        ShotResult back = s.simulate(7, 3.3, -2, 0, (TrajectoryListener) (t, x, y, vx, vy) -> min[0] = Math.min(min[0], x));
        assertEquals(5.25 + r, min[0], 1e-3);
        double v1Squared = 4 - 2 * mg * (7 - 5.25 - r), v2 = 0.82 * Math.sqrt(v1Squared);
        assertEquals(5.25 + r + v2 * v2 / (2 * mg), back.endX(), 1e-3);
    }

    /**
     * Magnets and repellers reach 127 px. Their strength makes our profile as deep as the original's
     * field: the original's pull towards the centre, averaged over the directions and integrated from
     * the rim in, computed here by quadrature from its rule (0.0005 (127 − d) px/tick², split between
     * the axes as |cos| and 1 − |cos|).
     */
    @Test
    void magnetsAreAsDeepAsTheOriginals() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 24, 6, TileMap.specialTile(20, PixelMap.GRASS));
        Tracks.set(codes, 24, 18, TileMap.specialTile(21, PixelMap.GRASS));
        List<Magnet> magnets = TrackConverterTest.convert(codes).course().magnets();
        assertEquals(2, magnets.size());
        Magnet pull = magnets.get(0), push = magnets.get(1);
        assertEquals(new Vec2(24.5 * 0.25, (25 - 6.5) * 0.25), pull.position());
        assertEquals(127 * PX, pull.radius(), 1e-12);
        assertEquals(-pull.strength(), push.strength());
        // The original's depth (px²/tick²): ∫ from 0 to 127 of the mean radial pull.
        int n = 2000;
        double depth = 0;
        for (int i = 0; i < n; i++) {
            double d = (i + 0.5) * 127.0 / n, radial = 0;
            for (int k = 0; k < n; k++) {
                double a = 2 * Math.PI * (k + 0.5) / n, cos = Math.abs(Math.cos(a)), sin = Math.abs(Math.sin(a));
                radial += 0.0005 * (127 - d) * (cos * cos + (1 - cos) * sin) / n;
            }
            depth += radial * 127.0 / n;
        }
        double depthSi = depth * PX * PX / (TICK * TICK);
        // Ours: the potential's rise from the centre to the rim, s R 9/16.
        assertEquals(depthSi, pull.strength() * pull.radius() * 9 / 16, 1e-4 * depthSi);
        assertEquals(1.640, pull.strength(), 1e-3);
    }

    /**
     * The blue teleport start sends the ball to one of the blue exits, drawn with a seed: a ball
     * rolling east along row 12 into it comes out at each of the three exits about a third of the
     * time, and the same shot always at the same one. The entry is where a probe 6 px from the
     * ball's centre touches the start (as the original tests).
     */
    @Test
    void teleportsDrawTheirExits(@TempDir Path dir) throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 20, 12, TileMap.specialTile(8, PixelMap.GRASS));
        int[] exitRows = {4, 8, 20};
        for (int row : exitRows) Tracks.set(codes, 30, row, TileMap.specialTile(9, PixelMap.GRASS));
        TrackConverter.Converted t = TrackConverterTest.convert(codes);
        Course c = t.course();
        assertEquals(1, c.teleports().size());
        Teleport tp = c.teleports().get(0);
        assertNotNull(tp.seed());
        assertEquals(3, tp.exits().size());
        double cy = (25 - 12.5) * 0.25, cx = 20.5 * 0.25;
        assertTrue(tp.entry().contains(cx - 6 * PX, cy) && tp.entry().contains(cx, cy));
        assertTrue(!tp.entry().contains(cx - 15 * PX, cy));
        // It reads back with its seed.
        World w = World.load(TrackConverterTest.write(t, dir));
        assertEquals(c.teleports(), w.course().teleports());
        Simulator s = new Simulator(w, minigolf.physics.SimulationSettings.DEFAULT);
        int[] count = new int[3];
        for (int k = 0; k < 150; k++) {
            double speed = 2.5 + k * 0.005;
            ShotResult r = s.simulate(c.start().x(), cy, speed, 0, 0, null);
            StrokeEvent e = r.events().stream().filter(v -> v.type() == StrokeEvent.Type.TELEPORT).findFirst().orElseThrow();
            assertEquals(30.5 * 0.25, e.x(), 1e-12);
            int row = (int) Math.round(25 - 0.5 - e.y() / 0.25);
            count[row == 4 ? 0 : row == 8 ? 1 : 2]++;
            assertEquals(r.endX(), s.simulate(c.start().x(), cy, speed, 0).endX());
        }
        for (int k : count) assertTrue(k > 25 && k < 75, java.util.Arrays.toString(count));
    }

    /** Starts that lead only to each other cannot be played with our teleports: left out, and the notes say so. */
    @Test
    void startsLeadingToEachOtherAreLeftOutWithANote() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 20, 4, TileMap.specialTile(14, PixelMap.GRASS));
        Tracks.set(codes, 30, 4, TileMap.specialTile(14, PixelMap.GRASS));
        TrackConverter.Converted t = TrackConverterTest.convert(codes);
        assertEquals(0, t.course().teleports().size());
        assertTrue(t.notes().contains("teleports: the green starts lead to each other; not played"), t.notes().toString());
    }
}
