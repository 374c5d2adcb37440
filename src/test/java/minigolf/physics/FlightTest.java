package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.Vec2;
import minigolf.terrain.Terrain;
import minigolf.course.PhysicsSettings;
import org.junit.jupiter.api.Test;

/** Chips, drag, bounces, take-offs: closed forms and invariants. */
class FlightTest {
    private static final double G = TestWorlds.G;

    private static World flat(double drag, Double groundRestitution) {
        return TestObstacles.withFlight(TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20), drag, groundRestitution);
    }

    private static StrokeEvent first(ShotResult r, StrokeEvent.Type... types) {
        return r.events().stream().filter(e -> List.of(types).contains(e.type())).findFirst().orElseThrow();
    }

    @Test
    void withoutDragTheFirstLandingIsAtTheParabolasRange() {
        ShotResult r = TestWorlds.rk4(flat(0, null)).simulate(-5, 0, 3, 1, 2.5, null);
        StrokeEvent landing = first(r, StrokeEvent.Type.BOUNCE, StrokeEvent.Type.LAND);
        double time = 2 * 2.5 / G;
        assertEquals(-5 + 3 * time, landing.x(), 1e-3);
        assertEquals(1 * time, landing.y(), 1e-3);
        assertEquals(time, landing.t(), 1e-9);
        assertEquals(0.1, landing.z(), 1e-12);
        assertEquals(StrokeEvent.Type.LAUNCH, r.events().get(0).type());
        assertEquals(Math.sqrt(9 + 1 + 2.5 * 2.5), landing.speedBefore(), 1e-9, "energy kept in the air without drag");
    }

    @Test
    void dragShortensTheFlight() {
        double noDrag = first(TestWorlds.rk4(flat(0, null)).simulate(-5, 0, 3, 0, 3, null), StrokeEvent.Type.BOUNCE).x();
        double golf = first(TestWorlds.rk4(flat(0.5, null)).simulate(-5, 0, 3, 0, 3, null), StrokeEvent.Type.BOUNCE).x();
        double heavy = first(TestWorlds.rk4(flat(5, null)).simulate(-5, 0, 3, 0, 3, null), StrokeEvent.Type.BOUNCE).x();
        assertTrue(golf < noDrag && heavy < golf, noDrag + " > " + golf + " > " + heavy);
        // Golf-ball drag at these speeds is small: k |v| ~ 0.016 * 4 m/s^2, about 1% over 0.6 s.
        assertEquals(noDrag + 5, golf + 5, 0.02 * (noDrag + 5));
    }

    @Test
    void aBallThrownStraightUpBouncesLowerEachTimeAndComesToRest() {
        for (Double e : new Double[] {null, 0.6}) {
            ShotResult r = TestWorlds.rk4(flat(0.5, e)).simulate(1, 2, 0, 0, 4, null);
            List<StrokeEvent> bounces = r.events().stream().filter(x -> x.type() == StrokeEvent.Type.BOUNCE).toList();
            assertTrue(bounces.size() >= 3, r.events().toString());
            for (int k = 1; k < bounces.size(); k++) {
                assertTrue(bounces.get(k).speedAfter() < bounces.get(k - 1).speedAfter(), "lower each time");
            }
            if (e != null) assertEquals(0.6, bounces.get(1).speedAfter() / bounces.get(1).speedBefore(), 1e-9);
            else assertEquals(GroundImpact.pennerRestitution(bounces.get(0).speedBefore()),
                    bounces.get(0).speedAfter() / bounces.get(0).speedBefore(), 1e-9);
            assertEquals(Outcome.STOPPED, r.outcome());
            assertEquals(1, r.endX(), 1e-12);
            assertEquals(2, r.endY(), 1e-12);
            assertEquals(0.1, r.endZ(), 1e-12);
            assertEquals(StrokeEvent.Type.LAND, r.events().get(r.events().size() - 2).type());
        }
    }

    @Test
    void onTheMoonABallKeepsBouncingUntilItsHopIsUnderAMillimetreOfMoonGravity() {
        // e = 0.5, no drag, vz 1 m/s: bounces leave at 0.5, 0.25, 0.125, 0.0625 m/s. A 1 mm hop is
        // 0.057 m/s at g = 1.62 (the course's gravity), so all four fly; with Earth's 0.14 m/s
        // threshold the ball would settle after two.
        World earth = flat(0, 0.5);
        PhysicsSettings p = earth.physics();
        World moon = new World(earth.course().withPhysics(new PhysicsSettings(1.62, p.kineticFriction(),
                p.staticFriction(), p.maxSpeed(), p.model(), p.ballRadius(), p.ballMass(), 0, p.airDensity(), 0.5)),
                earth.terrain());
        ShotResult r = TestWorlds.rk4(moon).simulate(1, 2, 0, 0, 1, null);
        assertEquals(4, r.events().stream().filter(e -> e.type() == StrokeEvent.Type.BOUNCE).count(), r.events().toString());
        assertEquals(2, TestWorlds.rk4(earth).simulate(1, 2, 0, 0, 1, null).events().stream()
                .filter(e -> e.type() == StrokeEvent.Type.BOUNCE).count());
    }

    @Test
    void chipsAreDeterministic() {
        World w = TestObstacles.with(flat(0.5, null), List.of(new Obstacle.Tree(new Vec2(-2, 0.3), 0.1, 1, 0.7),
                new Obstacle.Wall(new Vec2(0, -3), new Vec2(0, 3), 0.1, 0.15, 0.7)));
        ShotResult a = TestWorlds.rk4(w).simulate(-5, 0, 3, 0.4, 2, null);
        ShotResult b = TestWorlds.rk4(w).simulate(-5, 0, 3, 0.4, 2, null);
        assertEquals(a, b);
        assertTrue(a.events().size() > 3);
    }

    @Test
    void aChipClearsALowWallThatStopsARoll() {
        World w = TestObstacles.with(flat(0.5, null), List.of(new Obstacle.Wall(new Vec2(0, -3), new Vec2(0, 3), 0.1, 0.15, 0.7)));
        ShotResult roll = TestWorlds.rk4(w).simulate(-3, 0, 4, 0, 0, null);
        assertTrue(roll.endX() < 0, roll.toString());
        assertEquals(StrokeEvent.Type.COLLISION, roll.events().get(0).type());
        ShotResult chip = TestWorlds.rk4(w).simulate(-1, 0, 2.8, 0, 2.8, null);
        assertTrue(chip.endX() > 0, chip.toString());
        assertTrue(chip.events().stream().noneMatch(e -> e.type() == StrokeEvent.Type.COLLISION), chip.events().toString());
    }

    /** A course that plays putts only (a classic track): the chip over the wall is played along the ground. */
    @Test
    void onAPuttsOnlyCourseAChipIsPlayedAsThePuttBeneathIt() {
        World w = TestObstacles.with(flat(0.5, null), List.of(new Obstacle.Wall(new Vec2(0, -3), new Vec2(0, 3), 0.1, 0.15, 0.7)));
        World putts = new World(w.course().withPhysics(w.physics().withPuttsOnly(true)), w.terrain());
        ShotResult chip = TestWorlds.rk4(putts).simulate(-1, 0, 2.8, 0, 2.8, null);
        ShotResult putt = TestWorlds.rk4(putts).simulate(-1, 0, 2.8, 0, 0, null);
        assertTrue(chip.endX() < 0, chip.toString());
        assertEquals(putt.endX(), chip.endX(), 0);
        assertEquals(putt.endY(), chip.endY(), 0);
        assertTrue(chip.events().stream().noneMatch(e -> e.type() == StrokeEvent.Type.LAUNCH), chip.events().toString());
        assertEquals(StrokeEvent.Type.COLLISION, chip.events().get(0).type());
    }

    /** A plateau at h = 3 for x < 0, then a drop of slope 1. */
    private static World cliff() {
        Terrain cliff = new Terrain() {
            public double height(double x, double y) {
                return x < 0 ? 3 : 3 - x;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = height(x, y);
                out[1] = x < 0 ? 0 : -1;
                out[2] = 0;
            }
        };
        return TestObstacles.withFlight(TestWorlds.world(cliff, 0.1, 0.2, 20), 0, null);
    }

    @Test
    void aBallRollingOffAnEdgeTakesOffThere() {
        // A plateau at h = 3 for x < 0, then a drop of slope 1: at 3 m/s the ground falls away
        // faster than the ball can fall, so it flies and lands further down.
        World w = cliff();
        ShotResult r = TestWorlds.rk4(w).simulate(-2, 0, 4, 0, 0, null);
        StrokeEvent launch = first(r, StrokeEvent.Type.LAUNCH);
        assertEquals(0, launch.x(), 4 * (1.0 / 60), "takes off within a step (6 cm) of the edge");
        StrokeEvent landing = first(r, StrokeEvent.Type.BOUNCE, StrokeEvent.Type.LAND);
        // Free flight from the edge at speed v: lands where 3 - x = 3 - g x^2 / (2 v^2), x = 2 v^2 / g.
        double v = Math.sqrt(16 - 2 * 0.1 * G * 2);
        double x = 2 * v * v / G;
        assertEquals(x, landing.x(), 0.1);
    }

    @Test
    void aBallRollingOffAnEdgeTakesOffAtTheEdgeWhereverItsStepsFall() {
        // The same drop, the ball started at 25 positions so the edge falls anywhere in a step
        // (and in the step control's sub-steps): it leaves at the edge, never rolls over it first
        // (a ball once launched 23 mm past it, on the slope, and landed at once).
        World w = cliff();
        for (int k = 0; k < 25; k++) {
            double start = -2 - k * 0.0029;
            ShotResult r = TestWorlds.rk4(w).simulate(start, 0, 4, 0, 0, null);
            StrokeEvent launch = first(r, StrokeEvent.Type.LAUNCH);
            assertTrue(launch.x() <= 1e-4 && launch.x() > -0.01, "start " + start + ": launch at " + launch.x());
            StrokeEvent landing = first(r, StrokeEvent.Type.BOUNCE, StrokeEvent.Type.LAND);
            assertTrue(landing.x() > 2, "start " + start + ": lands at " + landing.x());
        }
    }

    @Test
    void landingInTheHoleSlowlyIsHoledAndInWaterIsWater() {
        Hole hole = new Hole(new Vec2(2, 0), 0.1, HoleRule.REST, null);
        World w = TestObstacles.withFlight(
                TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.CLASSIC, hole, List.of()), 0, null);
        ShotResult up = TestWorlds.rk4(w).simulate(2.05, 0, 0, 0, 3, null);
        assertEquals(Outcome.HOLED, up.outcome());
        assertEquals(2 * 3 / G, up.time(), 1e-3);
        ShotResult fast = TestWorlds.rk4(w).simulate(2 - 3 * 2 * 2 / G, 0, 3, 0, 2, null);
        assertTrue(fast.outcome() != Outcome.HOLED || fast.time() > 2 * 2 / G + 0.1, "a fast landing bounces over the hole");

        World lake = TestObstacles.withFlight(TestWorlds.world(TestWorlds.lake(), 0.08, 0.2, 5), 0, null);
        ShotResult splash = TestWorlds.rk4(lake).simulate(-3, 0, 2.5, 0, 1.5, null);
        assertEquals(Outcome.WATER, splash.outcome());
        assertEquals(0, splash.endZ(), 1e-12, "on the water's surface");
        assertTrue(Math.abs(splash.endX()) < Math.sqrt(-8 * Math.log(0.9)));
    }
}
