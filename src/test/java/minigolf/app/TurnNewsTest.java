package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The line at the bottom after a stroke says whose turn follows: during a bot's turn it read
 * "Ann: 3.0 m to the hole", a person's news under the bot's "is thinking" panel.
 */
class TurnNewsTest {
    @TempDir
    Path dir;

    @Test
    void aPersonsStrokeNewsNamesTheBotWhoseTurnItIs() throws Exception {
        World tee = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/holes/01-first-tee.json"));
        List<String> said = new ArrayList<>();
        PlaySession play = new PlaySession(tee, null, List.of(), new PlayerFiles(new SettingsStore(dir), s -> { }), said::add);
        play.start(List.of(Player.human("Ann"), Player.bot("Bot (Hard)", "hard")), UserSettings.DEFAULTS);
        // A gentle putt towards the hole: it stops short, on the green.
        double dx = tee.hole().position().x() - tee.course().start().x(), dy = tee.hole().position().y() - tee.course().start().y();
        double d = Math.hypot(dx, dy);
        play.hit(1.0 * dx / d, 1.0 * dy / d, 0);
        for (int i = 0; i < 2000 && play.animator() != null; i++) play.advance(0.02, 1, false);
        play.advance(0.02, 1, false);
        PlayerState ann = play.game().player(0);
        String news = String.format(Locale.ROOT, "Ann: %.1f m to the hole; Bot (Hard) to play",
                Math.hypot(ann.x() - tee.hole().position().x(), ann.y() - tee.hole().position().y()));
        assertEquals(news, said.get(said.size() - 1));
        assertNotNull(play.botTurn(), "the bot's turn has begun");
        assertTrue(play.game().players().get(play.game().currentPlayer()).isBot());
    }

    @Test
    void aLonePlayersNewsHasNoTurn() throws Exception {
        World tee = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/holes/01-first-tee.json"));
        List<String> said = new ArrayList<>();
        PlaySession play = new PlaySession(tee, null, List.of(), new PlayerFiles(new SettingsStore(dir), s -> { }), said::add);
        play.start(List.of(Player.human("Ann")), UserSettings.DEFAULTS);
        play.hit(0.3, 0, 0);
        for (int i = 0; i < 2000 && play.animator() != null; i++) play.advance(0.02, 1, false);
        String last = said.get(said.size() - 1);
        assertTrue(last.matches("\\d+\\.\\d m to the hole"), last);
    }
}
