package minigolf.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.physics.World;
import minigolf.game.RoundLoader;
import minigolf.game.SettingsStore;

/**
 * The README's picture of the New game screen (tools/readme-screenshots.sh): Meadowbrook's 18 holes
 * chosen, two people and a computer opponent, its levels in view. Usage: NewGameScreenshot OUT.png
 */
public final class NewGameScreenshot {
    private NewGameScreenshot() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path config = Files.createTempDirectory("minigolf-shot");
        World world = World.load(Path.of("courses", "holes", "01-first-tee.json"));
        GameApp app = new GameApp(world, new GameApp.Options(null, out, 12, null, List.of(), 1,
                new SettingsStore(config), true, false));
        var round = RoundLoader.load(Path.of("courses", "rounds", "meadowbrook-18.json"));
        app.onLoopPass((pass, window) -> {
            if (pass != 1) return;
            app.play().chooseRound(round);
            NewGameScreen form = app.screens().newGame();
            app.setScreen(form);
            form.players(3);
            form.typeName(0, "Ann");
            form.typeName(1, "Bob");
            form.typeName(2, "Player 3");
            form.chooseOpponent(2, "hard");
        });
        app.run();
    }
}
