package minigolf.bot.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.CancellationToken;
import minigolf.bot.search.SpeedGuess;
import minigolf.course.CourseException;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The planner's maps take push zones and teleports into account (issue 24). */
class ElementMapsTest {
    static World course(String extra) throws CourseException {
        return World.parse("{\"format\": 1, \"name\": \"maps\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -2], \"max\": [5, 2]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1}, " + extra + "}", "maps.json");
    }

    private static double cell(DistanceField field, double x, double y) {
        return field.cellDistance(field.grid().indexOf(x, y));
    }

    @Test
    void aTeleportsEntryIsAsNearTheHoleAsItsExit() throws CourseException {
        World w = course("\"teleports\": [{\"entry\": {\"type\": \"circle\", \"center\": [-3, 1], \"radius\": 0.3},"
                + " \"exits\": [{\"position\": [3.5, 0]}]}]");
        DistanceField field = new DistanceField(CourseGrid.of(w, CancellationToken.none()), 4, 0, CancellationToken.none());
        assertEquals(cell(field, 3.5, 0), cell(field, -3, 1), 1e-12);
        assertTrue(cell(field, -3, 1) < 0.6, "the far corner is half a metre from the hole: " + cell(field, -3, 1));
        // Two metres below the entry's centre (1.7 m from its rim) the way to the hole is through it, not the 7 m across.
        assertEquals(1.7 + cell(field, 3.5, 0), cell(field, -3, -1), 0.06);
    }

    @Test
    void aPushAlongTheWayShortensItAndOneAgainstItLengthensIt() throws CourseException {
        World with = course("\"pushZones\": [{\"shape\": {\"type\": \"rect\", \"min\": [-5, -2], \"max\": [5, 2]}, \"push\": [0.5, 0]}]");
        DistanceField field = new DistanceField(CourseGrid.of(with, CancellationToken.none()), 4, 0, CancellationToken.none());
        DistanceField plain = new DistanceField(CourseGrid.of(course("\"zones\": []"), CancellationToken.none()), 4, 0,
                CancellationToken.none());
        // A step along the push costs 1 - 0.5/(mu_k g) = 0.49 of a plain one, against it 1.51.
        assertEquals(0.49 * cell(plain, -3, 0), cell(field, -3, 0), 0.05);
        assertEquals(1.51 * cell(plain, 4.8, 0), cell(field, 4.8, 0), 0.05);
        // The speed guess counts the push's work: 0.5 m/s^2 over 4 m gives 2 J/kg.
        double still = SpeedGuess.speed(course("\"zones\": []"), -4, -1, 4, 0, -1, 0);
        double pushed = SpeedGuess.speed(with, -4, -1, 4, 0, -1, 0);
        assertEquals(still * still - 2 * 2, pushed * pushed, 1e-9);
    }
}
