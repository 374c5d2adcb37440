package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The "realistic" setting: noisy strokes in the game, exact replays and saves. */
class RealisticGameTest {
    private static final NoiseModel NOISE = new NoiseModel(0.02, 0.1);

    @TempDir
    Path dir;

    private static Game realistic(long seed) {
        return new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 10,
                NOISE, seed);
    }

    private static void playOn(Game g, int shots) {
        for (int i = 0; i < shots && !g.isOver(); i++) {
            PlayerState s = g.player(g.currentPlayer());
            double[] v = GameTest.shot(s.x(), s.y(), 3, 0.5, 0.6 + 0.1 * (i % 4));
            g.play(v[0], v[1]);
        }
    }

    @Test
    void theHistoryHoldsThePlayedStrokeAndReplaysExactly() {
        Game g = realistic(42);
        PlayerState s = g.player(g.currentPlayer());
        ShotRecord r = g.play(1.5, 0.2);
        assertNotEquals(1.5, r.vx(), "the noise changed the stroke");
        assertTrue(Math.abs(r.vx() - 1.5) < 0.6 && Math.abs(r.startX() - s.x()) < 0.12, r.toString());
        playOn(g, 8);
        assertTrue(HoleReplay.of(g).matchesPlay(), "a replay plays the played strokes");
        Game same = realistic(42);
        same.play(1.5, 0.2);
        playOn(same, 8);
        assertEquals(g.state(), same.state(), "same seed, same game");
    }

    @Test
    void aSavedRealisticGameGoesOnAsTheOriginal() throws Exception {
        Game original = realistic(7);
        playOn(original, 3);
        original.startShot(2.0, 0.3);
        for (int i = 0; i < 10; i++) original.activeStroke().step();
        Path file = dir.resolve("game.json");
        SavedGames.save(original, file);
        assertTrue(Files.readString(file).contains("\"noise\""));
        Game resumed = SavedGames.load(file).resume();
        assertEquals(NOISE, resumed.noise());
        original.finishShotNow();
        resumed.finishShotNow();
        assertEquals(original.state(), resumed.state(), "the stroke in flight is drawn again, the same");
        playOn(original, 10);
        playOn(resumed, 10);
        assertEquals(original.state(), resumed.state());
    }

    @Test
    void theSettingIsValidatedAndKept() throws Exception {
        SettingsStore store = new SettingsStore(dir.resolve("minigolf"));
        UserSettings s = UserSettings.DEFAULTS.withNoise(UserSettings.REALISTIC_POSITION, UserSettings.REALISTIC_VELOCITY)
                .withHideFrictionFromBots(true);
        store.save(s);
        assertEquals(s, store.load());
        assertEquals(new NoiseModel(0.01, 0.05), store.load().noise());
        assertThrows(IllegalArgumentException.class, () -> UserSettings.DEFAULTS.withNoise(-0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> UserSettings.DEFAULTS.withNoise(0, 2));
        Files.writeString(store.file(), "{\"noiseVelocity\": 5}");
        assertEquals(store.file() + ": noiseVelocity must be 0 to 1.0 m/s, got 5.0",
                assertThrows(SaveGameException.class, store::load).getMessage());
    }

    @Test
    void aBotPlayerIsToldTheNoise() {
        double x = GameTest.FLAT.course().start().x(), y = GameTest.FLAT.course().start().y();
        ShotPlanner robust = BotCatalog.planner("robust");
        ShotPlanner.Control control = new ShotPlanner.Control() {
            public void progress(double fraction, String message) {
            }

            public boolean isCancelled() {
                return false;
            }

            public void whenCancelled(Runnable action) {
            }
        };
        double[] exact = robust.plan(GameTest.FLAT, SimulationSettings.DEFAULT, x, y, 0, 3, control);
        double[] planner = BotCatalog.planner("planner").plan(GameTest.FLAT, SimulationSettings.DEFAULT, x, y, 0, 3, control);
        assertEquals(planner[0], exact[0], 0.0, "without noise, the planner's shot");
        double[] noisy = robust.plan(GameTest.FLAT, SimulationSettings.DEFAULT, x, y, 0, 3,
                new BotConditions(NOISE, false, List.of()), control);
        assertTrue(Double.isFinite(noisy[0]) && Math.hypot(noisy[0], noisy[1]) <= GameTest.FLAT.physics().maxSpeed());
    }

    /** A slow flat green (mu_k 0.16): a bot given hidden friction learns it from its first stroke. */
    @Test
    void aBotPlayerWithHiddenFrictionLearnsFromItsOwnStrokes() {
        World slow = minigolf.bot.friction.HiddenFrictionTestAccess.slowFlat();
        Game g = new Game(slow, SimulationSettings.DEFAULT, List.of(Player.bot("Robo", "planner")), 10);
        ShotPlanner planner = BotCatalog.planner("planner");
        ShotPlanner.Control control = new ShotPlanner.Control() {
            public void progress(double fraction, String message) {
            }

            public boolean isCancelled() {
                return false;
            }

            public void whenCancelled(Runnable action) {
            }
        };
        for (int stroke = 0; stroke < 2 && !g.isOver(); stroke++) {
            PlayerState s = g.player(0);
            double[] v = planner.plan(slow, SimulationSettings.DEFAULT, s.x(), s.y(), s.total(), stroke,
                    BotConditions.of(g, 0, true), control);
            g.play(v[0], v[1]);
        }
        assertEquals(2, g.history().size(), "the first stroke, planned on the prior (mu_k 0.1), stops short");
        assertTrue(g.player(0).status() == PlayerStatus.HOLED, "the second, on the estimate, holes: " + g.history());
    }
}
