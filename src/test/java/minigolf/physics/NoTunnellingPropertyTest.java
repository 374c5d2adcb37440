package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import minigolf.collision.CollisionScene;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;

/**
 * 10,000 seeded random shots at the maximum speed (a third of them chips) inside a pen of thin
 * fences, among trees, rotated boxes, a thick wall and an .obj mesh, on tilted ground: no ball
 * ever leaves the pen, none ends inside or touching an obstacle, no impact adds speed.
 */
class NoTunnellingPropertyTest {
    private static final double PEN = 3;
    private static final double R = 0.02135;
    private static final String OCTAHEDRON = String.join("\n", "v 1 0 0", "v -1 0 0", "v 0 1 0", "v 0 -1 0", "v 0 0 1", "v 0 0 -1",
            "f 1 3 5", "f 3 2 5", "f 2 4 5", "f 4 1 5", "f 3 1 6", "f 2 3 6", "f 4 2 6", "f 1 4 6");
    private static final double OCT_X = 1.5, OCT_Y = -1.5, OCT_Z = 1.0, OCT_SCALE = 0.4, OCT_TURN = 30;

    @Test
    void tenThousandMaxSpeedShotsNeverTunnelNorEndInsideNorGainSpeed() throws ObjException {
        Terrain ground = TestWorlds.plane(0.03, -0.02, 1);
        List<Obstacle> obstacles = new ArrayList<>();
        double[][] pen = {{-PEN, -PEN}, {PEN, -PEN}, {PEN, PEN}, {-PEN, PEN}};
        for (int k = 0; k < 4; k++) {
            obstacles.add(new Obstacle.Wall(new Vec2(pen[k][0], pen[k][1]), new Vec2(pen[(k + 1) % 4][0], pen[(k + 1) % 4][1]),
                    0, 1.5, 0.8));
        }
        obstacles.add(new Obstacle.Tree(new Vec2(-1.5, 1.2), 0.12, 2, 0.6));
        obstacles.add(new Obstacle.Tree(new Vec2(0.8, 1.9), 0.08, 2, 0.6));
        obstacles.add(new Obstacle.Tree(new Vec2(-2.2, -2.1), 0.2, 2, 0.6));
        obstacles.add(new Obstacle.Box(new Vec3(1.2, 0.4, 0), new Vec3(2.2, 0.9, 1.15), 25, 0.7));
        obstacles.add(new Obstacle.Box(new Vec3(-1.4, -1.0, 0), new Vec3(-0.9, -0.7, 1.3), -40, 0.9));
        obstacles.add(new Obstacle.Wall(new Vec2(-0.5, 1.0), new Vec2(0.6, 1.3), 0.08, 0.1, 0.7));
        obstacles.add(new Obstacle.Wall(new Vec2(0.7, -0.8), new Vec2(0.7, -2.4), 0, 0.05, 1.0));
        obstacles.add(new Obstacle.Model("octahedron.obj", new Vec3(OCT_X, OCT_Y, OCT_Z), OCT_TURN, OCT_SCALE, 0.75,
                ObjParser.parse(OCTAHEDRON)));
        World world = TestObstacles.with(TestWorlds.world(ground, 0.1, 0.2, 6, PhysicsModel.CLASSIC, TestWorlds.farHole(6), List.of()),
                obstacles);
        CollisionScene scene = world.obstacles();
        Simulator simulator = TestWorlds.rk4(world);
        SplittableRandom random = new SplittableRandom(20240603L);
        int[] steps = {0};
        for (int shot = 0; shot < 10_000; shot++) {
            double a = random.nextDouble() * 2 * Math.PI;
            double x0 = 0.3 * Math.cos(a), y0 = 0.3 * Math.sin(a);
            double direction = random.nextDouble() * 2 * Math.PI;
            double lift = shot % 3 == 0 ? random.nextDouble() * 1.2 : 0; // a third are chips, up to 50 degrees
            double vx = 5 * Math.cos(direction) * Math.cos(lift), vy = 5 * Math.sin(direction) * Math.cos(lift);
            double vz = 5 * Math.sin(lift);
            int number = shot;
            ShotResult r = simulator.simulate(x0, y0, vx, vy, vz, new TrajectoryListener() {
                public void onStep(double t, double x, double y, double vx, double vy) {
                }

                public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
                    steps[0]++;
                    if (Math.abs(x) > PEN - R + 1e-6 || Math.abs(y) > PEN - R + 1e-6) {
                        fail("shot " + number + " crossed a fence at (" + x + ", " + y + ", " + z + ")");
                    }
                }

                public void onEvent(StrokeEvent e) {
                    if (!Double.isNaN(e.speedBefore()) && e.speedAfter() > e.speedBefore() * (1 + 1e-9)) {
                        fail("shot " + number + ": impact gained speed: " + e);
                    }
                }
            });
            assertNotEquals(Outcome.TIMEOUT, r.outcome(), "shot " + number);
            double x = r.endX(), y = r.endY(), z = r.endZ();
            assertTrue(Math.abs(x) < PEN && Math.abs(y) < PEN, "shot " + number + " ended outside the pen: " + r);
            double clearance = scene.clearance(x, y, z + R);
            assertTrue(clearance >= R - 1e-6, "shot " + number + " ends touching or inside an obstacle (" + clearance + "): " + r);
            assertTrue(!insideAny(obstacles, x, y, z + R), "shot " + number + " ends inside an obstacle: " + r);
        }
        assertTrue(steps[0] > 1_000_000, "the shots did roll: " + steps[0] + " steps");
    }

    /** Whether the point lies inside a box, a trunk or the octahedron. */
    private static boolean insideAny(List<Obstacle> obstacles, double x, double y, double z) {
        for (Obstacle o : obstacles) {
            if (o instanceof Obstacle.Box b) {
                double cx = (b.min().x() + b.max().x()) / 2, cy = (b.min().y() + b.max().y()) / 2;
                double turn = Math.toRadians(-b.rotationDeg());
                double lx = Math.cos(turn) * (x - cx) - Math.sin(turn) * (y - cy);
                double ly = Math.sin(turn) * (x - cx) + Math.cos(turn) * (y - cy);
                if (Math.abs(lx) < (b.max().x() - b.min().x()) / 2 && Math.abs(ly) < (b.max().y() - b.min().y()) / 2
                        && z > b.min().z() && z < b.max().z()) {
                    return true;
                }
            } else if (o instanceof Obstacle.Tree t) {
                if (Math.hypot(x - t.position().x(), y - t.position().y()) < t.radius() && z < 3) return true;
            } else if (o instanceof Obstacle.Model) {
                double turn = Math.toRadians(-OCT_TURN);
                double lx = Math.cos(turn) * (x - OCT_X) - Math.sin(turn) * (y - OCT_Y);
                double ly = Math.sin(turn) * (x - OCT_X) + Math.cos(turn) * (y - OCT_Y);
                if (Math.abs(lx) + Math.abs(ly) + Math.abs(z - OCT_Z) < OCT_SCALE) return true;
            }
        }
        return false;
    }
}
