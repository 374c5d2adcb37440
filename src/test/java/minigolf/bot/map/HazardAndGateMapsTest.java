package minigolf.bot.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.CancellationToken;
import minigolf.course.CourseException;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The bots' maps see water drawn as hazard zones (the classic tracks' pools, flat terrain) and the
 * one-way gates' way. Before, a hazard zone was free ground to the grid and a gate was no obstacle
 * at all, so the planner routed straight over the water and back through gates the wrong way.
 */
class HazardAndGateMapsTest {
    private static final CancellationToken NONE = CancellationToken.none();

    /** Flat, 10 m x 4 m, start (-4, 0), hole (4, 0), mu_k 0.1, ball radius 0.1. */
    static World course(String extra) throws CourseException {
        return World.parse("{\"format\": 1, \"name\": \"maps\", \"terrain\": {\"height\": \"0\"},"
                + " \"bounds\": {\"min\": [-5, -2], \"max\": [5, 2]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2, \"ballRadius\": 0.1},"
                + " \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1}, " + extra + "}", "maps.json");
    }

    /** A pool across the middle, x -0.5..0.5, from the lower edge up to y = 1: the way round passes above it. */
    private static String pool(String when) {
        return "\"zones\": [{\"shape\": {\"type\": \"rect\", \"min\": [-0.5, -2], \"max\": [0.5, 1]},"
                + " \"kineticFriction\": 0.1, \"staticFriction\": 0.2, \"hazard\": {\"when\": \"" + when + "\"}}]";
    }

    private static DistanceField field(World w) {
        return new DistanceField(CourseGrid.of(w, NONE), 4, 0, NONE);
    }

    private static double cell(DistanceField field, double x, double y) {
        return field.cellDistance(field.grid().indexOf(x, y));
    }

    @Test
    void aHazardZoneTheBallMayNotEnterIsWaterToTheMaps() throws CourseException {
        World w = course(pool("enter"));
        assertTrue(CourseGrid.isBlocked(w, 0, 0));
        assertTrue(CourseGrid.lost(w, 0, -1));
        assertFalse(CourseGrid.isBlocked(w, 0, 1.5), "above the pool is free");
        DistanceField field = field(w);
        assertEquals(Double.POSITIVE_INFINITY, field.at(0, 0));
        // Round the pool: at least to its corners and back, 2 * hypot(3.5, 1) + 1 = 8.28 m (straight across: 8).
        double around = 2 * Math.hypot(3.5, 1) + 1;
        assertTrue(cell(field, -4, 0) > around, "round the pool: " + cell(field, -4, 0));
        assertTrue(cell(field, -4, 0) < around + 1.5, "not much further: " + cell(field, -4, 0));
        // The path passes above the pool.
        for (double[] p : field.path(-4, 0)) {
            if (Math.abs(p[0]) <= 0.5) assertTrue(p[1] > 1, "path point in the pool: " + p[0] + ", " + p[1]);
        }
    }

    @Test
    void aBallMayRollAcrossShallowWaterButNoRestIsPlannedInIt() throws CourseException {
        World w = course(pool("rest"));
        assertFalse(CourseGrid.isBlocked(w, 0, 0));
        CourseGrid grid = CourseGrid.of(w, NONE);
        assertEquals(0, grid.hazardClearance(0, 0), 1e-12);
        // 0.7 m from the shallow water (2 m from the course's edge, all a course without it would see).
        assertEquals(0.7, grid.hazardClearance(-1.2, 0), 2 * grid.cell());
        assertEquals(2, CourseGrid.of(course("\"zones\": []"), NONE).hazardClearance(-1.2, 0), 2 * grid.cell());
        // Passable (dearer near it, as beside any water), never dearer than the pool the ball may not enter.
        double plain = cell(field(course("\"zones\": []")), -4, 0);
        double shallow = cell(field(w), -4, 0);
        double deep = cell(field(course(pool("enter"))), -4, 0);
        assertTrue(Double.isFinite(field(w).at(0, 0)), "a ball in the shallow water still has a way to the hole");
        assertTrue(plain < shallow && shallow <= deep, "plain " + plain + ", shallow " + shallow + ", deep " + deep);
    }

    @Test
    void aOneWayGateIsPassedOnlyAlongItsWay() throws CourseException {
        // A wall across the course at x = 0 with a one-way gate in it from y = -1 to 1.
        String walls = "{\"type\": \"wall\", \"from\": [0, -2], \"to\": [0, -1], \"thickness\": 0.05, \"height\": 0.1},"
                + " {\"type\": \"wall\", \"from\": [0, 1], \"to\": [0, 2], \"thickness\": 0.05, \"height\": 0.1}";
        // Seen from (0, -1) looking to (0, 1), the left side is -x: the gate lets the ball go towards -x only.
        World back = course("\"obstacles\": [" + walls + ", {\"type\": \"gate\", \"from\": [0, -1], \"to\": [0, 1],"
                + " \"height\": 0.1, \"passTo\": \"left\"}]");
        assertEquals(Double.POSITIVE_INFINITY, cell(field(back), -4, 0), "the way to the hole at +x is barred");
        assertEquals(Double.POSITIVE_INFINITY, field(back).at(-4, 0));
        assertTrue(field(back).path(-4, 0).isEmpty());
        World along = course("\"obstacles\": [" + walls + ", {\"type\": \"gate\", \"from\": [0, -1], \"to\": [0, 1],"
                + " \"height\": 0.1, \"passTo\": \"right\"}]");
        assertEquals(8, cell(field(along), -4, 0), 0.1);
        assertTrue(GateCrossings.segmentsCross(-1, 0, 1, 0, 0, -1, 0, 1));
        assertFalse(GateCrossings.segmentsCross(-1, 0, -0.5, 0, 0, -1, 0, 1));
    }
}
