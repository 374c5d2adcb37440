package minigolf.online;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Rooms on the same round hold each hole's world once, however their players are named; their games stay their own. */
class StartSavesTest {
    private static World flat(double hx) throws Exception {
        return World.parse("{\"format\": 1, \"name\": \"StartSaves " + hx + "\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-3, 0], \"hole\": {\"position\": [" + hx + ", 0], \"radius\": 0.1}}", "flat");
    }

    private static String startOf(Round round, String... names) {
        List<Player> players = java.util.Arrays.stream(names).map(Player::human).toList();
        return SavedRounds.toJson(new RoundGame(round, SimulationSettings.DEFAULT, players, 10));
    }

    @Test
    void roomsWithOtherPlayersShareEachHolesWorld() throws Exception {
        Round round = new Round("Two", List.of(new Round.Hole("a.json", 2, flat(1.25)), new Round.Hole("b.json", 3, flat(2.5))),
                "test");
        String ann = startOf(round, "Ann", "Bob"), cyd = startOf(round, "Cyd", "Dee");
        RoundGame a = StartSaves.read(ann, "room AAAA"), c = StartSaves.read(cyd, "room CCCC");
        for (int h = 0; h < 2; h++) {
            assertSame(a.round().hole(h).world(), c.round().hole(h).world(), "hole " + (h + 1));
        }
        assertNotSame(a.round().hole(0).world(), a.round().hole(1).world());
        assertEquals(1.25, a.round().hole(0).world().course().hole().position().x(), 1e-12);
        assertEquals(2.5, c.round().hole(1).world().course().hole().position().x(), 1e-12);
        // The games are each room's own: a stroke in one leaves the other at the start.
        assertNotSame(a.game(), c.game());
        a.game().play(0.5, 0);
        assertEquals(1, a.game().player(0).total());
        assertEquals(0, c.game().player(0).total());
        assertEquals("Cyd", c.game().players().get(0).name());
    }
}
