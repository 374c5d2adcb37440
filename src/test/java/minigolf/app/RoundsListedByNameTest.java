package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The rounds in course select are in the order a player reads them (shorter first, then by name),
 * not by file name: "Red Rock Canyon" (canyon-18.json) came before "Meadowbrook Front Nine".
 */
class RoundsListedByNameTest {
    @TempDir
    Path config;

    @Test
    void shippedRoundsShorterFirstThenByNameAndThePlayersOwnAfterThem() throws Exception {
        // File names in the opposite order of the names.
        OwnRounds.write(config, "a.json", "Zebra Two", 2);
        OwnRounds.write(config, "b.json", "alpine Two", 2);
        OwnRounds.write(config, "c.json", "Quick One", 1);
        List<CourseFolders.RoundEntry> rounds = CourseFolders.rounds(new SettingsStore(config));
        List<String> names = rounds.stream().map(r -> r.round().name()).toList();
        assertEquals(List.of("Quick One", "alpine Two", "Zebra Two"), names.subList(names.size() - 3, names.size()), names.toString());
        List<CourseFolders.RoundEntry> shipped = rounds.subList(0, rounds.size() - 3);
        for (int i = 1; i < shipped.size(); i++) {
            var a = shipped.get(i - 1).round();
            var b = shipped.get(i).round();
            assertTrue(a.size() < b.size() || a.size() == b.size() && a.name().compareToIgnoreCase(b.name()) <= 0, names.toString());
        }
        assertTrue(names.indexOf("Meadowbrook Front Nine") == 0 && names.indexOf("Red Rock Canyon") > names.indexOf("Meadowbrook 18"),
                names.toString());
    }
}
