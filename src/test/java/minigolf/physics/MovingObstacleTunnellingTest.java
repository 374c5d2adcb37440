package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import minigolf.course.Course;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import org.junit.jupiter.api.Test;

/**
 * No tunnelling through moving obstacles (issue 24): 10,000 seeded shots at up to the maximum
 * speed (a third of them chips) in a round pen where a cross of thin blades (1 cm thick, half a
 * ball's radius) turns at 0.5, 1 or 2 revolutions per second, either way round, from a random
 * moment of the clock. The blades reach to 2 cm from the pen's fence, less than the ball's
 * diameter, so the four sectors between the blades are closed: a ball can only change sector by
 * passing through a blade. At every state the ball's centre must stay in its sector, at least a
 * ball radius from the blades (their pose computed here, separately from the engine).
 */
class MovingObstacleTunnellingTest {
    private static final double R = 0.02135;
    private static final double RING = 1.0, TIP = 0.98, HALF_THICKNESS = 0.005;
    private static final int FENCES = 48;

    @Test
    void tenThousandShotsNeverCrossATurningBlade() {
        double[] revolutionsPerSecond = {0.5, -1, 2, -2, 1, -0.5};
        SplittableRandom random = new SplittableRandom(24_2024L);
        int[] states = {0};
        int shots = 10_000, crushed = 0;
        for (int world = 0; world < revolutionsPerSecond.length; world++) {
            double rate = revolutionsPerSecond[world];
            double phase = 0.37 * world;
            Simulator simulator = new Simulator(pen(rate, phase), new SimulationSettings(Integrator.RK4, 1.0 / 60, 2.0));
            int count = world < revolutionsPerSecond.length - 1 ? shots / revolutionsPerSecond.length
                    : shots - (revolutionsPerSecond.length - 1) * (shots / revolutionsPerSecond.length);
            for (int i = 0; i < count; i++) {
                double clock = random.nextDouble() * 10;
                int sector = random.nextInt(4);
                // A start well inside the sector at that moment: 0.2 to 0.8 m out, 20 to 70 degrees from its first blade.
                double angle = blades(rate, phase, clock) + sector * Math.PI / 2 + Math.toRadians(20 + 50 * random.nextDouble());
                double distance = 0.2 + 0.6 * random.nextDouble();
                double x0 = distance * Math.cos(angle), y0 = distance * Math.sin(angle);
                double direction = random.nextDouble() * 2 * Math.PI;
                double speed = 5 * Math.sqrt(random.nextDouble());
                double lift = i % 3 == 0 ? random.nextDouble() * 1.2 : 0;
                double vx = speed * Math.cos(direction) * Math.cos(lift), vy = speed * Math.sin(direction) * Math.cos(lift);
                double vz = speed * Math.sin(lift);
                String shot = "rate " + rate + " shot " + i;
                ShotResult r = simulator.simulateAt(clock, x0, y0, vx, vy, vz, new TrajectoryListener() {
                    public void onStep(double t, double x, double y, double vx, double vy) {
                    }

                    public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
                        states[0]++;
                        double relative = Math.atan2(y, x) - blades(rate, phase, clock + t);
                        double within = relative - sector * Math.PI / 2;
                        within -= 2 * Math.PI * Math.floor(within / (2 * Math.PI));
                        double d = Math.hypot(x, y);
                        // Distance from the centre to the sector's two blades (each a line through the axis).
                        double toFirst = d * Math.sin(Math.min(within, Math.PI / 2));
                        double toSecond = d * Math.sin(Math.max(0, Math.PI / 2 - within));
                        boolean inSector = within <= Math.PI / 2;
                        if (!inSector || (Math.min(toFirst, toSecond) < HALF_THICKNESS + R - 1e-6 && d < TIP + R)) {
                            fail(shot + " left its sector at t = " + t + ": (" + x + ", " + y + ", " + z + "), "
                                    + Math.toDegrees(within) + " degrees into it");
                        }
                        if (d > RING) fail(shot + " left the pen: " + d);
                    }
                });
                if (r.outcome() == Outcome.OUT) crushed++;
            }
        }
        assertTrue(states[0] > 500_000, "the shots did roll: " + states[0] + " states");
        assertTrue(crushed < shots / 2, "most shots are not crushed: " + crushed);
    }

    /** The angle of the first blade at a moment of the clock (the blades are at it and every quarter turn on). */
    private static double blades(double rate, double phase, double clock) {
        return 2 * Math.PI * rate * (clock + phase);
    }

    /** The round pen of fences, and the turning cross: one turn every 1/|rate| s, clockwise for rate &lt; 0. */
    private static World pen(double rate, double phase) {
        List<Obstacle> obstacles = new ArrayList<>();
        for (int k = 0; k < FENCES; k++) {
            double a = 2 * Math.PI * k / FENCES, b = 2 * Math.PI * (k + 1) / FENCES;
            obstacles.add(new Obstacle.Wall(new Vec2(RING * Math.cos(a), RING * Math.sin(a)),
                    new Vec2(RING * Math.cos(b), RING * Math.sin(b)), 0, 2, 0.8));
        }
        Motion turn = new Motion.Rotate(new Vec3(0, 0, 0), new Vec3(0, 0, Math.signum(rate)), 1 / Math.abs(rate), phase);
        obstacles.add(new Obstacle.Moving(new Obstacle.Box(new Vec3(-TIP, -HALF_THICKNESS, -1), new Vec3(TIP, HALF_THICKNESS, 3), 0, 0.7), turn));
        obstacles.add(new Obstacle.Moving(new Obstacle.Box(new Vec3(-HALF_THICKNESS, -TIP, -1), new Vec3(HALF_THICKNESS, TIP, 3), 0, 0.7), turn));
        Course base = ElementWorlds.flat("").course();
        return World.of(base.withObstacles(obstacles));
    }
}
