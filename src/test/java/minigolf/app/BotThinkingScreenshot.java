package minigolf.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;

/**
 * The picture of a computer opponent thinking, as a player sees it (tools/readme-screenshots.sh,
 * docs/playing.md): Ann has putted on the first tee, and the frame is the third one drawn while
 * Hard plans its stroke. Usage: BotThinkingScreenshot OUT.png [--notice] (exit code 1 if no frame showed
 * it); {@code --notice}: with a settings file that cannot be read, so its notice is at the top too.
 */
public final class BotThinkingScreenshot {
    private BotThinkingScreenshot() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path config = Files.createTempDirectory("minigolf-shot");
        if (List.of(args).contains("--notice")) BrokenSettings.in(config);
        Path course = Path.of("courses", "holes", "01-first-tee.json");
        // Ann's putt stops short of the cup (3 m/s on the first tee's green); then Hard's turn.
        GameApp app = new GameApp(minigolf.physics.World.load(course), new GameApp.Options(course, out, 2000,
                List.of(Player.human("Ann"), Player.bot("Bot (Hard)", "hard")), List.of(new double[]{3.0, 0.05}), 1,
                new SettingsStore(config), true, false));
        // The third frame of the turn: a new panel takes its size in its second frame.
        int[] thinking = {0};
        app.finishWhen(() -> (app.play().botTurn() != null ? ++thinking[0] : (thinking[0] = 0)) >= 3);
        app.run();
        if (thinking[0] < 3) {
            System.err.println("no frame showed the bot thinking");
            System.exit(1);
        }
    }
}
