package minigolf.editor.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import minigolf.cli.MinigolfCommand;
import org.junit.jupiter.api.Test;

/** "Play it" starts a game on the tee: the game's command line with a player, which the CLI accepts. */
class PlayItTest {
    @Test
    void playItStartsAGameWithAPlayer() {
        List<String> args = EditorApp.playArguments(Path.of("/tmp/x/.editor-play.json"));
        assertEquals(List.of("play", "/tmp/x/.editor-play.json", "--players", "Player"), args);
        picocli.CommandLine cl = new picocli.CommandLine(new MinigolfCommand());
        picocli.CommandLine.ParseResult parsed = cl.parseArgs(args.toArray(new String[0]));
        assertEquals(List.of("Player"), parsed.subcommand().matchedOptionValue("--players", List.of()));
    }
}
