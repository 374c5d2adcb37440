package minigolf.game;


import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.physics.SimulationSettings;

/**
 * A game's complete state, what a save file holds besides the course: who plays, each ball and
 * count, the shots so far, the shot in flight (null when the balls are at rest), the course
 * clock (s; where moving obstacles are; with a shot in flight, the moment it was played), and the
 * seed the game's computer opponents draw their decisions from ({@link Game#botSeed()}).
 */
public record GameState(SimulationSettings settings, List<Player> players, int strokeLimit,
                        List<PlayerState> states, List<ShotRecord> history, PendingShot pendingShot, NoiseModel noise,
                        long noiseSeed, double clock, long botSeed) {
    /** A game whose bots draw from seed 0 (a save from before the bots' seed was kept). */
    public GameState(SimulationSettings settings, List<Player> players, int strokeLimit, List<PlayerState> states,
                     List<ShotRecord> history, PendingShot pendingShot, NoiseModel noise, long noiseSeed, double clock) {
        this(settings, players, strokeLimit, states, history, pendingShot, noise, noiseSeed, clock, 0);
    }

    /** A game at course clock 0. */
    public GameState(SimulationSettings settings, List<Player> players, int strokeLimit, List<PlayerState> states,
                     List<ShotRecord> history, PendingShot pendingShot, NoiseModel noise, long noiseSeed) {
        this(settings, players, strokeLimit, states, history, pendingShot, noise, noiseSeed, 0);
    }

    /** A game without noise. */
    public GameState(SimulationSettings settings, List<Player> players, int strokeLimit, List<PlayerState> states,
                     List<ShotRecord> history, PendingShot pendingShot) {
        this(settings, players, strokeLimit, states, history, pendingShot, NoiseModel.NONE, 0);
    }

    public GameState {
        if (noise == null) noise = NoiseModel.NONE;
        if (!Double.isFinite(clock) || clock < 0) throw new IllegalArgumentException("the course clock must be finite and >= 0, got " + clock);
        players = List.copyOf(players);
        states = List.copyOf(states);
        history = List.copyOf(history);
        if (players.size() != states.size()) {
            throw new IllegalArgumentException(players.size() + " players but " + states.size() + " ball states");
        }
    }
}
