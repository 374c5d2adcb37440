package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Small things a player noticed, without a window: names typed in New game are offered again (also
 * after a restart; they were forgotten), a bot's turn is announced without "drag back from the
 * ball", and the HUD names a bot once ("Bot (planner) (bot: planner) to play" before).
 */
class NewGameNamesTest {
    @TempDir
    Path dir;

    private GameApp app() {
        return new GameApp(GameLauncher.loadBundled("/courses/flat.json"), new GameApp.Options(null, null, 0, null, List.of(),
                1, new SettingsStore(dir), false, false));
    }

    @Test
    void namesTypedInNewGameAreOfferedTheNextTime() {
        GameApp first = app();
        NewGameScreen form = first.screens().newGame();
        first.setScreen(form);
        assertEquals("Player 1", form.name(0));
        form.typeName(0, "Zoe");
        form.typeName(1, "Max");
        form.teeOff();
        assertEquals(List.of("Zoe", "Max"), first.game().players().stream().map(Player::name).toList());
        first.setScreen(first.screens().mainMenu());
        first.setScreen(form);
        assertEquals("Zoe", form.name(0), "kept in this session");
        GameApp restarted = app();
        restarted.setScreen(restarted.screens().newGame());
        assertEquals("Zoe", restarted.screens().newGame().name(0), "and after a restart");
        assertEquals("Max", restarted.screens().newGame().name(1));
    }

    @Test
    void aBotsTurnIsAnnouncedWithoutTheAimingHintAndNamedOnce() {
        assertFalse(PlaySession.teeOff(Player.bot("Bot (planner)", "planner")).toLowerCase().contains("drag"));
        assertTrue(PlaySession.teeOff(Player.human("Ann")).contains("drag back from the ball"));
        assertEquals("Bot (planner) to play", Hud.turnLine(Player.bot("Bot (planner)", "planner")));
        assertEquals("Robo to play (computer)", Hud.turnLine(Player.bot("Robo", "planner")));
        assertEquals("Ann to play", Hud.turnLine(Player.human("Ann")));
    }

    @Test
    void opponentsAreOfferedByLevelMediumFirstAndAlgorithmsOnlyInPracticeMode() {
        GameApp app = app();
        NewGameScreen form = app.screens().newGame();
        app.setScreen(form);
        assertEquals(List.of("easy", "medium", "hard", "pro"), form.opponents(), "a player's choice: the levels");
        assertEquals(List.of("Easy", "Medium", "Hard", "Pro"),
                form.opponents().stream().map(minigolf.game.BotCatalog::label).toList());
        form.typeName(0, "Ann");
        form.chooseOpponent(1, "hard");
        assertEquals("Bot (Hard)", form.name(1), "an untyped name follows the seat's level");
        form.chooseOpponent(1, "medium");
        assertEquals("Bot (Medium)", form.name(1));
        form.teeOff();
        Player bot = app.game().players().get(1);
        assertEquals("medium", bot.bot(), "Medium, the default opponent");
        assertEquals("Bot (Medium)", bot.name(), "a computer seat left as Player 2 is named after its level");
        // Practice mode: every bot by its algorithm's name too (the levels first).
        app.applySettings(app.settings().withPractice(true));
        assertTrue(form.opponents().containsAll(List.of("easy", "pro", "planner", "astar")), form.opponents().toString());
    }
}
