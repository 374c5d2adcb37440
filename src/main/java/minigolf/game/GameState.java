package minigolf.game;


import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.physics.SimulationSettings;

/**
 * A game's complete state, what a save file holds besides the course: who plays, each ball and
 * count, the shots so far, and the shot in flight (null when the balls are at rest).
 */
public record GameState(SimulationSettings settings, List<Player> players, int strokeLimit,
                        List<PlayerState> states, List<ShotRecord> history, PendingShot pendingShot, NoiseModel noise,
                        long noiseSeed) {
    /** A game without noise. */
    public GameState(SimulationSettings settings, List<Player> players, int strokeLimit, List<PlayerState> states,
                     List<ShotRecord> history, PendingShot pendingShot) {
        this(settings, players, strokeLimit, states, history, pendingShot, NoiseModel.NONE, 0);
    }

    public GameState {
        if (noise == null) noise = NoiseModel.NONE;
        players = List.copyOf(players);
        states = List.copyOf(states);
        history = List.copyOf(history);
        if (players.size() != states.size()) {
            throw new IllegalArgumentException(players.size() + " players but " + states.size() + " ball states");
        }
    }
}
