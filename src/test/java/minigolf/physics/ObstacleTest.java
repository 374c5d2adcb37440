package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** Bounces off obstacles against closed forms: reflection, restitution, sliding along walls. */
class ObstacleTest {
    private static final double R = 0.02135;

    /** Flat ground without friction, a fence along x = 1 (from y = -5 to 5). */
    private static World fenced(double restitution, double muK) {
        World flat = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), muK, 0.2, 10);
        return TestObstacles.with(flat, List.of(new Obstacle.Wall(new Vec2(1, -5), new Vec2(1, 5), 0, 0.3, restitution)));
    }

    private static Stroke shoot(World world, double x, double y, double vx, double vy, List<StrokeEvent> events) {
        return new Stroke(world, SimulationSettings.DEFAULT, x, y, vx, vy, 0, TestObstacles.collect(events), true);
    }

    @Test
    void headOnTheNormalSpeedIsMultipliedByTheRestitution() {
        List<StrokeEvent> events = new ArrayList<>();
        Stroke s = TestObstacles.stepUntil(shoot(fenced(0.7, 0), 0, 0, 3, 0, events), events, StrokeEvent.Type.COLLISION, 1);
        StrokeEvent hit = events.get(0);
        assertEquals(StrokeEvent.Type.COLLISION, hit.type());
        assertEquals(1 - R, hit.x(), 1e-6, "the ball's centre stops one radius before the fence");
        assertEquals((1 - R) / 3, hit.t(), 1e-6);
        assertEquals(3, hit.speedBefore(), 1e-12);
        assertEquals(2.1, hit.speedAfter(), 1e-12);
        assertEquals(-2.1, s.vx(), 1e-12);
        assertEquals(0, s.vy(), 1e-12);
    }

    @Test
    void aBrakingBallMeetsTheFenceAtTheClosedFormsMoment() {
        // Straight at the fence with friction: x(t) = 3 t - mu g t^2 / 2 reaches 1 - R at
        // t = (3 - sqrt(9 - 2 mu g (1 - R))) / (mu g). The contact's time is found on the path's
        // sixteenths (PathSweep), not as the chord's fraction (off by up to mu g tau^2 / 8 / v).
        double braking = 0.1 * 9.81, v = Math.sqrt(9 - 2 * braking * (1 - R));
        List<StrokeEvent> events = new ArrayList<>();
        TestObstacles.stepUntil(shoot(fenced(0.7, 0.1), 0, 0, 3, 0, events), events, StrokeEvent.Type.COLLISION, 1);
        StrokeEvent hit = events.get(0);
        assertEquals(1 - R, hit.x(), 2e-7, "the ball's centre stops one radius (and the skin) before the fence");
        assertEquals((3 - v) / braking, hit.t(), 1e-7);
        assertEquals(v, hit.speedBefore(), 1e-6);
    }

    @Test
    void at45DegreesTheAngleAndTheSpeedComeOutExact() {
        double v = 3 / Math.sqrt(2);
        for (double e : new double[] {1.0, 0.7}) {
            List<StrokeEvent> events = new ArrayList<>();
            Stroke s = TestObstacles.stepUntil(shoot(fenced(e, 0), 0, 0, v, v, events), events, StrokeEvent.Type.COLLISION, 1);
            assertEquals(-e * v, s.vx(), 1e-12, "normal part times e");
            assertEquals(v, s.vy(), 1e-12, "tangential part kept");
            if (e == 1) assertEquals(135, Math.toDegrees(Math.atan2(s.vy(), s.vx())), 1e-9);
            assertEquals(3 * Math.sqrt((1 + e * e) / 2), events.get(0).speedAfter(), 1e-12);
        }
    }

    @Test
    void aBallRolledAlongAWallNeitherSticksNorJitters() {
        // Touching the fence, rolling parallel to it: exactly the free flat-ground stop, no contact.
        List<StrokeEvent> events = new ArrayList<>();
        ShotResult r = shoot(fenced(0.7, 0.1), 1 - R - 1e-9, -4, 0, 3, events).run();
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-4 + 9 / (2 * 0.1 * TestWorlds.G), r.endY(), 1e-6);
        assertTrue(events.stream().noneMatch(e -> e.type() == StrokeEvent.Type.COLLISION), events.toString());

        // Into the fence at 2 degrees with e = 0: one contact, then it slides along, its x never
        // beyond the contact and never wobbling back.
        List<StrokeEvent> slide = new ArrayList<>();
        double a = Math.toRadians(2);
        List<double[]> path = new ArrayList<>();
        Stroke s = new Stroke(fenced(0, 0.1), SimulationSettings.DEFAULT, 1 - R - 0.01, -4, 3 * Math.sin(a), 3 * Math.cos(a), 0,
                new TrajectoryListener() {
                    public void onStep(double t, double x, double y, double vx, double vy) {
                        path.add(new double[] {x, y});
                    }

                    public void onEvent(StrokeEvent event) {
                        slide.add(event);
                    }
                }, true);
        ShotResult end = s.run();
        assertEquals(1, slide.stream().filter(e -> e.type() == StrokeEvent.Type.COLLISION).count(), slide.toString());
        double contactX = slide.get(0).x();
        for (int k = 1; k < path.size(); k++) {
            assertTrue(path.get(k)[0] <= 1 - R, "never into the fence");
            if (path.get(k)[1] > slide.get(0).y()) assertEquals(contactX, path.get(k)[0], 1e-9, "slides straight along");
            assertTrue(path.get(k)[1] >= path.get(k - 1)[1], "no jitter back");
        }
        assertEquals(slide.get(0).speedBefore() * Math.cos(a), slide.get(0).speedAfter(), 1e-9,
                "e = 0 keeps exactly the tangential part");
        assertEquals(Outcome.STOPPED, end.outcome());
    }

    @Test
    void aFastBallCannotPassAThinFenceOnASlope() {
        // Downhill towards the fence (the slope pushes the ball into it): it ends on its own side.
        World tilted = TestWorlds.world(TestWorlds.plane(-0.1, 0, 2), 0.05, 0.3, 10, PhysicsModel.CLASSIC,
                TestWorlds.farHole(10), List.of());
        World fenced = TestObstacles.with(tilted, List.of(new Obstacle.Wall(new Vec2(1, -11), new Vec2(1, 11), 0, 0.3, 0.7)));
        for (double angle = -80; angle <= 80; angle += 0.5) {
            double a = Math.toRadians(angle);
            ShotResult r = TestWorlds.rk4(fenced).simulate(0, 0, 5 * Math.cos(a), 5 * Math.sin(a));
            assertTrue(r.endX() <= 1 - R, "angle " + angle + ": " + r);
        }
    }
}
