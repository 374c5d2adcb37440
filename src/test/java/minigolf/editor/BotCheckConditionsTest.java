package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.NoiseModel;
import minigolf.bot.friction.HiddenFrictionTestAccess;
import minigolf.game.BotCatalog;
import minigolf.game.ShotPlanner;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** "Ask a bot" under the player's settings: hidden friction and the "realistic" noise change what the bot can do. */
class BotCheckConditionsTest {
    private static final ShotPlanner.Control NEVER_CANCELLED = new ShotPlanner.Control() {
        public void progress(double f, String m) {
        }

        public boolean isCancelled() {
            return false;
        }

        public void whenCancelled(Runnable a) {
        }
    };

    @Test
    void withFrictionHiddenTheBotMustLearnTheSlowGreenFirst() {
        World slow = HiddenFrictionTestAccess.slowFlat(); // mu_k 0.16, the prior 0.1: a first putt on the prior runs long
        BotCheck.Result known = BotCheck.play(BotCatalog.planner("planner"), slow, SimulationSettings.DEFAULT, 12, 1,
                NEVER_CANCELLED);
        BotCheck.Result hidden = BotCheck.play(BotCatalog.planner("planner"), slow, SimulationSettings.DEFAULT, 12, 1,
                new BotCheck.Conditions(NoiseModel.NONE, true), NEVER_CANCELLED);
        assertTrue(known.holed() && hidden.holed(), known.describe() + " / " + hidden.describe());
        assertEquals(1, known.strokes(), known.describe());
        assertTrue(hidden.strokes() >= 2 && hidden.strokes() <= 3, hidden.describe());
        assertTrue(hidden.describe().endsWith("(friction hidden)"), hidden.describe());
    }

    @Test
    void underRealisticNoiseTheStrokesStrayAndTheSeedRepeatsThem() {
        World slow = HiddenFrictionTestAccess.slowFlat();
        BotCheck.Conditions realistic = new BotCheck.Conditions(new NoiseModel(0.05, 0.3), false);
        int[] strokes = new int[6];
        boolean anyOverOne = false;
        for (int seed = 1; seed <= 6; seed++) {
            BotCheck.Result r = BotCheck.play(BotCatalog.planner("planner"), slow, SimulationSettings.DEFAULT, 12, seed,
                    realistic, NEVER_CANCELLED);
            BotCheck.Result again = BotCheck.play(BotCatalog.planner("planner"), slow, SimulationSettings.DEFAULT, 12, seed,
                    realistic, NEVER_CANCELLED);
            assertEquals(r, again, "the same seed plays the same check");
            strokes[seed - 1] = r.strokes();
            anyOverOne |= r.strokes() > 1;
            assertTrue(r.describe().endsWith("(realistic)"), r.describe());
        }
        // Without noise the planner aces this green; with a spread of 0.3 m/s a 9 m putt does not always drop.
        assertTrue(anyOverOne, java.util.Arrays.toString(strokes));
    }
}
