package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.RoundLoader;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A round against computer opponents, saved in the middle of a hole and resumed, goes on with the
 * strokes the unbroken round played: the bots' seed is saved with the round (before, a resume drew
 * a new one, so Easy and Hard misplayed every stroke after it differently).
 */
class ResumedBotsTest {
    /** Holes played in all: the round is saved on the second, after this many strokes of it. */
    private static final int HOLES = 3, SAVED_AFTER = 2;

    @TempDir
    Path dir;

    private final List<String> said = new ArrayList<>();

    @Test
    void aResumedRoundReplaysTheUnbrokenRoundsBotStrokes() throws Exception {
        Path root = Path.of(System.getProperty("minigolf.projectDir", "."));
        SettingsStore store = new SettingsStore(dir);
        Round nine = RoundLoader.load(root.resolve("courses/rounds/meadowbrook-9.json"));
        PlaySession unbroken = new PlaySession(nine.hole(0).world(), null, List.of(), new PlayerFiles(store, said::add), said::add);
        unbroken.chooseRound(nine);
        unbroken.start(List.of(Player.bot("Bot (Easy)", "easy"), Player.bot("Bot (Hard)", "hard")), UserSettings.DEFAULTS);
        playUntil(unbroken, 1, SAVED_AFTER);
        unbroken.save();
        Path saved;
        try (Stream<Path> files = Files.list(store.savesDirectory())) {
            saved = files.filter(p -> p.getFileName().toString().startsWith("round-")).findFirst().orElseThrow();
        }
        playUntil(unbroken, HOLES, 0);
        List<List<List<Object>>> expected = strokes(unbroken.round());

        PlaySession resumed = new PlaySession(nine.hole(0).world(), null, List.of(), new PlayerFiles(store, said::add), said::add);
        assertTrue(resumed.load(saved), String.join("; ", said));
        assertEquals(1, resumed.round().holeIndex());
        assertEquals(SAVED_AFTER, resumed.game().history().size());
        playUntil(resumed, HOLES, 0);
        List<List<List<Object>>> again = strokes(resumed.round());
        assertEquals(HOLES, expected.size());
        assertTrue(expected.get(1).size() > SAVED_AFTER, "strokes after the save: " + expected.get(1).size());
        for (int h = 0; h < HOLES; h++) assertEquals(expected.get(h), again.get(h), "hole " + (h + 1));
    }

    /**
     * Every finished hole's strokes: who, from where, the velocity, the outcome and where it ended.
     * Not the course clock: a resumed game asks its bot one frame after the load, where the unbroken
     * game asked it in the frame its opponent's ball stopped, so the clock runs one frame longer.
     */
    private static List<List<List<Object>>> strokes(RoundGame round) {
        List<List<List<Object>>> all = new ArrayList<>();
        for (int h = 0; h < round.holesFinished(); h++) {
            all.add(round.holeStrokes(h).stream().map(r -> List.<Object>of(r.player(), r.startX(), r.startY(), r.vx(), r.vy(),
                    r.vz(), r.outcome(), r.endX(), r.endY())).toList());
        }
        return all;
    }

    /**
     * Plays on until hole {@code hole} (0-based) has {@code strokes} strokes with no ball rolling, or,
     * with {@code strokes} 0, until {@code hole} holes are finished.
     */
    private static void playUntil(PlaySession play, int hole, int strokes) throws InterruptedException {
        long deadline = System.nanoTime() + 600_000_000_000L;
        while (System.nanoTime() < deadline) {
            RoundGame round = play.round();
            if (strokes == 0 && round.holesFinished() >= hole) return;
            // (The next bot may be thinking already: its decision depends on the saved state alone.)
            if (strokes > 0 && round.holeIndex() == hole && round.game().history().size() == strokes
                    && !round.game().isShotInFlight() && play.animator() == null) {
                return;
            }
            if (play.botTurn() != null && !play.botTurn().isDone()) {
                Thread.sleep(2); // the bot thinks on its own thread; no play time passes meanwhile
                continue;
            }
            PlaySession.Progress p = play.advance(0.05, 20, false);
            if (p == PlaySession.Progress.OVER && !play.nextHole() && round.holesFinished() < hole) {
                throw new AssertionError("the round ended after " + round.holesFinished() + " holes");
            }
        }
        throw new AssertionError("not reached within 10 minutes: hole " + (hole + 1) + ", " + strokes + " strokes");
    }
}
