package minigolf.game;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.physics.SimulationSettings;

/**
 * A round played by 1 to 4 players: hole after hole, each hole a {@link Game} with the same
 * players, rules and stroke limit. When a hole's game is over its scores go on the card
 * ({@link #finishHole()}) and the next hole starts ({@link #nextHole()}); after the last hole the
 * round is over and {@link #scorecard()} names the winner. Plain Java, like {@link Game}.
 *
 * <p>With noise (the "realistic" setting) every hole is played with it; hole h's noise stream is
 * seeded by the round's seed plus h times a fixed odd constant, so a restored round recovers the
 * round's seed from the saved hole and plays the holes after it as the original would.
 */
public final class RoundGame {
    private final Round round;
    private final List<Player> players;
    private final SimulationSettings settings;
    private final int strokeLimit;
    private final NoiseModel noise;
    private final long noiseSeed;
    /** The seed every hole's computer opponents draw from (the same on every hole: BotTurn.seed mixes in the hole). */
    private final long botSeed;
    /** The strokes of each finished hole, as played (empty for holes of a save from before they were kept). */
    private final List<List<ShotRecord>> finishedStrokes = new ArrayList<>();
    /** scores[hole][seat]; only the first {@link #finished} rows are filled. */
    private final int[][] scores;
    private int finished;
    private int holeIndex;
    private Game game;

    /** Mixed into the round's seed once per hole (odd, so every hole of a round gets its own stream). */
    static final long HOLE_SEED_STEP = 0xD1B54A32D192ED03L;

    public RoundGame(Round round, SimulationSettings settings, List<Player> players, int strokeLimit) {
        this(round, settings, players, strokeLimit, NoiseModel.NONE, 0);
    }

    /** A round played with noise on every stroke (the "realistic" setting), drawn from {@code noiseSeed}. */
    public RoundGame(Round round, SimulationSettings settings, List<Player> players, int strokeLimit, NoiseModel noise,
                     long noiseSeed) {
        this(round, settings, players, strokeLimit, noise, noiseSeed, 0);
    }

    /** As {@link #RoundGame(Round, SimulationSettings, List, int, NoiseModel, long)}, its bots drawing from {@code botSeed}. */
    public RoundGame(Round round, SimulationSettings settings, List<Player> players, int strokeLimit, NoiseModel noise,
                     long noiseSeed, long botSeed) {
        this(round, settings, players, strokeLimit, noise, noiseSeed, botSeed, 0, new int[0][], null);
    }

    private RoundGame(Round round, SimulationSettings settings, List<Player> players, int strokeLimit, NoiseModel noise,
                      long noiseSeed, long botSeed, int finished, int[][] done, Game current) {
        if (round == null) throw new IllegalArgumentException("a round must be given");
        this.round = round;
        this.settings = settings;
        this.players = List.copyOf(players);
        this.strokeLimit = strokeLimit;
        this.noise = noise == null ? NoiseModel.NONE : noise;
        this.noiseSeed = this.noise.isNone() ? 0 : noiseSeed;
        this.botSeed = botSeed;
        this.scores = new int[round.size()][];
        if (finished < 0 || finished > round.size() || done.length != finished) {
            throw new IllegalArgumentException("scores for " + done.length + " holes do not fit a round of " + round.size());
        }
        for (int h = 0; h < finished; h++) {
            if (done[h].length != this.players.size()) {
                throw new IllegalArgumentException("hole " + (h + 1) + " has " + done[h].length + " scores for "
                        + this.players.size() + " players");
            }
            for (int s : done[h]) {
                if (s < 1 || s > strokeLimit + 1) {
                    throw new IllegalArgumentException("hole " + (h + 1) + ": a score of " + s + " cannot happen with the stroke limit " + strokeLimit);
                }
            }
            scores[h] = done[h].clone();
        }
        this.finished = finished;
        this.holeIndex = Math.min(finished, round.size() - 1);
        this.game = current != null ? current : holeGame(holeIndex);
    }

    /**
     * Rebuilds a round from saved parts: the scores of the holes finished so far and the game on
     * the current hole (which must be the round's next hole, with the same players).
     */
    public static RoundGame restore(Round round, int[][] finishedScores, Game current) {
        return restore(round, finishedScores, List.of(), current);
    }

    /**
     * As {@link #restore(Round, int[][], Game)}, with the strokes of the finished holes (for "watch
     * hole N again"); holes beyond {@code strokes}' size have none.
     */
    public static RoundGame restore(Round round, int[][] finishedScores, List<List<ShotRecord>> strokes, Game current) {
        if (strokes.size() > finishedScores.length) {
            throw new IllegalArgumentException("strokes for " + strokes.size() + " holes, but " + finishedScores.length + " are finished");
        }
        if (finishedScores.length < round.size() && !current.world().course().equals(round.hole(finishedScores.length).world().course())) {
            throw new IllegalArgumentException("the saved hole is not hole " + (finishedScores.length + 1) + " of the round");
        }
        int hole = Math.min(finishedScores.length, round.size() - 1);
        long roundSeed = current.noiseSeed() - HOLE_SEED_STEP * hole;
        RoundGame rg = new RoundGame(round, current.settings(), current.players(), current.strokeLimit(), current.noise(),
                roundSeed, current.botSeed(), finishedScores.length, finishedScores, current);
        for (int h = 0; h < finishedScores.length; h++) rg.finishedStrokes.add(h < strokes.size() ? List.copyOf(strokes.get(h)) : List.of());
        return rg;
    }

    /** The game on hole h, with the round's noise and that hole's stream. */
    private Game holeGame(int h) {
        return new Game(round.hole(h).world(), settings, players, strokeLimit, noise, noiseSeed + HOLE_SEED_STEP * h, botSeed);
    }

    /** The noise every stroke of the round is played with. */
    public NoiseModel noise() {
        return noise;
    }

    public Round round() {
        return round;
    }

    public List<Player> players() {
        return players;
    }

    public int strokeLimit() {
        return strokeLimit;
    }

    /** The hole being played (0-based); after the last hole, the last hole. */
    public int holeIndex() {
        return holeIndex;
    }

    public Round.Hole hole() {
        return round.hole(holeIndex);
    }

    /** The game on the current hole. */
    public Game game() {
        return game;
    }

    /** How many holes are on the card. */
    public int holesFinished() {
        return finished;
    }

    /** True once the current hole's game is over but its scores are not on the card yet. */
    public boolean isHoleOver() {
        return game.isOver() && finished == holeIndex;
    }

    /** True when every hole is on the card. */
    public boolean isOver() {
        return finished == round.size();
    }

    /** Puts the current hole's scores on the card (once its game is over); returns them by seat. */
    public int[] finishHole() {
        if (!game.isOver()) throw new IllegalStateException("hole " + (holeIndex + 1) + " is still being played");
        if (finished > holeIndex) throw new IllegalStateException("hole " + (holeIndex + 1) + " is already on the card");
        int[] s = game.scorecard().lines().stream().mapToInt(ScoreLine::score).toArray();
        scores[holeIndex] = s;
        finishedStrokes.add(List.copyOf(game.history()));
        finished++;
        return s.clone();
    }

    /** Starts the next hole; false if the round is over (the game stays on the last hole). */
    public boolean nextHole() {
        if (finished <= holeIndex) throw new IllegalStateException("hole " + (holeIndex + 1) + " is not on the card yet");
        if (holeIndex + 1 >= round.size()) return false;
        holeIndex++;
        game = holeGame(holeIndex);
        return true;
    }

    /** The strokes of finished hole h as played (empty where a save from before did not keep them). */
    public List<ShotRecord> holeStrokes(int h) {
        if (h < 0 || h >= finished) throw new IllegalArgumentException("hole " + (h + 1) + " is not finished");
        return finishedStrokes.get(h);
    }

    /** The scores of the finished holes, [hole][seat]. */
    public int[][] finishedScores() {
        int[][] out = new int[finished][];
        for (int h = 0; h < finished; h++) out[h] = scores[h].clone();
        return out;
    }

    /** The round's card: every finished hole, totals, par, and (once over) the winner. */
    public RoundScorecard scorecard() {
        List<RoundScorecard.Row> rows = new ArrayList<>();
        for (int seat = 0; seat < players.size(); seat++) {
            int[] perHole = new int[finished];
            for (int h = 0; h < finished; h++) perHole[h] = scores[h][seat];
            rows.add(new RoundScorecard.Row(players.get(seat).name(), perHole));
        }
        int[] pars = round.holes().stream().mapToInt(Round.Hole::par).toArray();
        return new RoundScorecard(round.name(), pars, rows, isOver());
    }

    @Override
    public String toString() {
        return round.name() + ": hole " + (holeIndex + 1) + " of " + round.size() + ", card " + Arrays.deepToString(finishedScores());
    }
}
