package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.SettingsStore;
import minigolf.online.server.CourseCatalog;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * "Play online" offers rounds and holes by the names a player reads (it asked for a file name
 * such as meadowbrook-9), and each is one a server on the shipped courses knows: the name sent
 * finds the same round there.
 */
class OnlineOffersTest {
    @TempDir
    Path config;

    @Test
    void everyOfferIsNamedAsAPlayerReadsItAndFoundOnTheServer() throws Exception {
        OwnRounds.write(config, "mine.json", "My Own", 1);
        SettingsStore store = new SettingsStore(config);
        assertTrue(CourseFolders.rounds(store).stream().anyMatch(r -> r.round().name().equals("My Own")), "the player's round loads");
        List<OnlineScreen.Offer> offers = OnlineScreen.offers(store);
        assertEquals(new OnlineScreen.Offer("Meadowbrook Front Nine (9 holes)", "meadowbrook-9"), offers.get(0));
        assertTrue(offers.contains(new OnlineScreen.Offer("First Tee (one hole)", "01-first-tee")), offers.toString());
        assertTrue(offers.stream().noneMatch(o -> o.label().startsWith("My Own") || o.serverName().equals("tee")),
                "the player's own round and its hole are not on the server: " + offers);
        CourseCatalog server = CourseCatalog.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses"),
                new PrintWriter(new StringWriter()));
        for (OnlineScreen.Offer o : offers) {
            CourseCatalog.Entry e = server.get(o.serverName());
            assertNotNull(e, o + " is not on the server");
            assertTrue(o.label().startsWith(e.round().name() + " ("), o + " is " + e.round().name() + " there");
        }
        assertTrue(offers.size() >= 5 + 18, "the five rounds and the eighteen holes: " + offers);
    }
}
