package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.course.Vec2;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Every ball on a spot of its own beside the tee: on every bundled course the spots are legal
 * (in play, dry, clear of obstacles, reached straight from the tee) and far enough apart that the
 * drawn balls do not overlap; the physics starts each player's stroke from that player's spot; the
 * players tee off in seat order.
 */
class TeeSpotsTest {
    private static Path courses() {
        return Path.of(System.getProperty("minigolf.projectDir", "."), "courses");
    }

    private static World flat(String obstacles, String height) throws CourseException {
        return World.parse("{\"format\": 1, \"name\": \"Tee\", \"terrain\": {\"height\": \"" + height + "\"},"
                + " \"bounds\": {\"min\": [-5, -3], \"max\": [5, 3]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-3, 0], \"hole\": {\"position\": [3, 0], \"radius\": 0.1}, \"obstacles\": [" + obstacles + "]}",
                "tee");
    }

    @Test
    void onEveryBundledCourseTheBallsStandApartOnLegalSpots() throws IOException {
        List<Path> files;
        try (Stream<Path> all = Files.walk(courses())) {
            files = all.filter(p -> p.toString().endsWith(".json") && !p.toString().contains("rounds")).sorted().toList();
        }
        List<String> shared = new ArrayList<>();
        int checked = 0;
        for (Path f : files) {
            World w;
            try {
                w = World.load(f);
            } catch (CourseException e) {
                continue; // not a course (a model list, a round)
            }
            Vec2 tee = w.course().start();
            assertEquals(List.of(tee), TeeSpots.of(w, 1), f + ": one player is on the tee");
            for (int n = 2; n <= Game.MAX_PLAYERS; n++) {
                List<Vec2> spots = TeeSpots.of(w, n);
                assertEquals(n, spots.size());
                checked++;
                if (spots.stream().allMatch(tee::equals)) {
                    shared.add(courses().relativize(f) + " (" + n + ")");
                    continue;
                }
                double[] g = new double[3];
                w.terrain().sample(tee.x(), tee.y(), g);
                for (int i = 0; i < n; i++) {
                    assertTrue(TeeSpots.legal(w, tee, spots.get(i), Math.hypot(g[1], g[2])), f + ": spot " + spots.get(i));
                    for (int j = 0; j < i; j++) {
                        double d = Math.hypot(spots.get(i).x() - spots.get(j).x(), spots.get(i).y() - spots.get(j).y());
                        assertTrue(d >= TeeSpots.MIN_SPACING - 1e-9, f + ": balls " + i + " and " + j + " " + d + " m apart");
                    }
                }
            }
        }
        assertTrue(checked > 150, "courses checked: " + checked / 3);
        // Meadowbrook's railed lanes have room beside every tee; no course shares the tee.
        assertEquals(List.of(), shared, "courses where the balls share the tee");
    }

    @Test
    void aWallBesideTheTeeSendsTheRowToTheOtherSideAndAPondBehind() throws CourseException {
        // A wall 0.1 m to the tee's left (seen towards the hole): the row reaches to the right.
        World walled = flat("{\"type\": \"wall\", \"from\": [-4, 0.1], \"to\": [-2, 0.1], \"thickness\": 0.04, \"height\": 0.1}",
                "0.1");
        List<Vec2> spots = TeeSpots.of(walled, 3);
        assertEquals(new Vec2(-3, 0), spots.get(0));
        for (Vec2 s : spots) {
            assertEquals(-3, s.x(), 1e-12, "across the line to the hole");
            assertTrue(s.y() <= 0, "right of the tee, away from the wall: " + s);
        }
        // Water on both sides (a causeway 0.24 m wide along the line to the hole): the balls line up behind the tee.
        World causeway = flat("", "0.15 - 10*y^2");
        for (Vec2 s : TeeSpots.of(causeway, 4)) {
            assertEquals(0, s.y(), 1e-12, "on the causeway: " + s);
            assertTrue(s.x() <= -3, "behind the tee: " + s);
        }
    }

    @Test
    void eachStrokeStartsFromItsPlayersSpotAndTeeingOffGoesInSeatOrder() throws CourseException {
        World w = flat("", "0.1");
        Game game = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob"),
                Player.human("Cy")), 10);
        List<Vec2> spots = TeeSpots.of(w, 3);
        assertEquals(List.of(new Vec2(-3, 0.16), new Vec2(-3, 0), new Vec2(-3, -0.16)), roundedSpots(spots),
                "a row across the line to the hole, centred on the tee, 0.16 m apart, Ann at the left");
        for (int i = 0; i < 3; i++) assertEquals(spots.get(i), new Vec2(game.player(i).x(), game.player(i).y()));
        // Ann plays backwards, farther from the hole than the others: still Bob, then Cy tee off.
        assertEquals(0, game.currentPlayer());
        ShotRecord ann = game.play(-1, 0);
        assertEquals(Outcome.STOPPED, ann.outcome());
        assertEquals(1, game.currentPlayer(), "Bob tees off next");
        ShotRecord bob = game.play(2, 0);
        assertEquals(spots.get(1).x(), bob.startX(), 0);
        assertEquals(spots.get(1).y(), bob.startY(), 0);
        assertEquals(2, game.currentPlayer(), "then Cy");
        ShotRecord cy = game.play(2, 0);
        assertEquals(spots.get(2).y(), cy.startY(), 0, "Cy's stroke starts from Cy's spot");
        assertEquals(spots.get(2).y(), cy.endY(), 1e-12, "a straight putt stays on its line");
        assertEquals(0, game.currentPlayer(), "then golf's order: Ann is farthest from the hole");
    }

    private static List<Vec2> roundedSpots(List<Vec2> spots) {
        return spots.stream().map(s -> new Vec2(Math.round(s.x() * 1e9) / 1e9, Math.round(s.y() * 1e9) / 1e9)).toList();
    }
}
