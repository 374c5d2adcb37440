package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.classic.ClassicIndex;
import minigolf.classic.ClassicScale;
import minigolf.classic.ShapeMasks;
import minigolf.classic.TrackImporter;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.SimulationSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The course select's "Classic tracks": listed from <config>/classic, searched, chosen, the players' best kept. */
class ClassicTracksSelectTest {
    @TempDir
    Path config;
    @TempDir
    Path tracks;

    /** A frame of blocks, the start at tile (4, 12), the hole at tile (44, 12) (written from the format description). */
    static final String MAP = "BAQQ48D" + "BAQQBAAA46DBAQQ" + "490E" + "BAQQBAAADDCAABAAA38DCBABAAADDBAQQ"
            + "BAQQBAAA46DBAQQ" + "490E" + "BAQQ48D";

    @Test
    void listedSearchedChosenAndScored() throws Exception {
        Files.createDirectories(tracks.resolve("hio"));
        Files.createDirectories(tracks.resolve("long"));
        Files.writeString(tracks.resolve("hio").resolve("a.track"), "V 1\nA Ann\nN Straight one\nT " + MAP + "\nI 100,250,1,40\n");
        Files.writeString(tracks.resolve("long").resolve("b.track"), "V 1\nA Bob\nN Long way\nT " + MAP + "\nI 10,200,9,1\n");
        TrackImporter.run(tracks, config.resolve("classic"), ShapeMasks.builtIn(), ClassicScale.standard());
        GameApp app = new GameApp(GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE), new GameApp.Options(null, null, 0, null,
                List.of(), 1, new SettingsStore(config), false, false));
        CourseSelectScreen select = app.screens().courseSelect();
        select.show();
        assertEquals(2, select.classic().tracks().size());
        assertEquals(2, select.classicMatches().size());
        ClassicIndex.Entry straight = select.classic().tracks().stream().filter(e -> e.name().equals("Straight one")).findFirst().orElseThrow();
        assertEquals(2.5, straight.averageStrokes(), 1e-12);
        assertEquals(1, straight.bestStrokes());
        assertTrue(straight.matches("ANN", "hio") && !straight.matches("", "long") && !straight.matches("bob", null));

        select.selectClassic(straight);
        assertEquals("Straight one", app.play().world().course().name());
        String key = CourseSelectScreen.scoreKey(straight);
        List<String> names = app.settings().playerNames();
        assertNull(app.files().classicBest(key, names));
        // A single game on it (one stroke each): the human's score is kept as the player's best.
        Game game = new Game(app.play().world(), SimulationSettings.DEFAULT, List.of(Player.human(names.get(0)),
                Player.bot("Robo", "planner")), 1, minigolf.bot.NoiseModel.NONE, 1);
        double speed = 0.8 * app.play().world().physics().maxSpeed();
        game.play(speed, 0);
        game.play(speed, 0);
        assertTrue(game.isOver());
        app.files().recordClassic(key, game);
        assertEquals(game.scorecard().lines().get(0).score(), app.files().classicBest(key, names));
        assertNull(app.files().classicBest(key, List.of("Robo")), "bots' scores are not kept");
    }

    @Test
    void noImportSaysHow() {
        GameApp app = new GameApp(GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE), new GameApp.Options(null, null, 0, null,
                List.of(), 1, new SettingsStore(config), false, false));
        CourseSelectScreen select = app.screens().courseSelect();
        select.show();
        assertTrue(select.classic().tracks().isEmpty());
        assertEquals(config.resolve("classic"), CourseFolders.classicFolder(app.files().store(), app.settings()));
        assertEquals(Path.of("/somewhere/else"),
                CourseFolders.classicFolder(app.files().store(), app.settings().withClassicFolder(" /somewhere/else ")));
    }
}
