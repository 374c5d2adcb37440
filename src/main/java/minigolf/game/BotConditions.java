package minigolf.game;

import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.bot.friction.FrictionEstimator;
import minigolf.physics.Outcome;

/**
 * What a bot player is told besides the course and its ball: the game's noise, whether friction is
 * hidden from it, (for the friction estimate) its own strokes so far on this hole, and the course
 * clock at the moment it is asked (where obstacles move). The game
 * records only the stroke as played, so that is what the estimate uses (the command line's
 * Playthrough uses the stroke the bot chose).
 */
public record BotConditions(NoiseModel noise, boolean hideFriction, List<OwnStroke> ownStrokes, double clock) {
    public static final BotConditions NONE = new BotConditions(NoiseModel.NONE, false, List.of());

    /** Conditions at course clock 0. */
    public BotConditions(NoiseModel noise, boolean hideFriction, List<OwnStroke> ownStrokes) {
        this(noise, hideFriction, ownStrokes, 0);
    }

    /** One of the bot's strokes: where it started, the shot, where it ended, and how. */
    public record OwnStroke(FrictionEstimator.Observation observation, Outcome outcome) {
    }

    public BotConditions {
        if (noise == null) noise = NoiseModel.NONE;
        ownStrokes = List.copyOf(ownStrokes);
    }

    /** The conditions of the bot in {@code seat} of {@code game}: its strokes from the game's history. */
    public static BotConditions of(Game game, int seat, boolean hideFriction) {
        List<OwnStroke> own = new java.util.ArrayList<>();
        for (ShotRecord r : game.history()) {
            if (r.player() != seat) continue;
            own.add(new OwnStroke(new FrictionEstimator.Observation(r.startX(), r.startY(),
                    minigolf.bot.Shot.of(r.vx(), r.vy()), r.endX(), r.endY()), r.outcome()));
        }
        // The clock stands still while the bot thinks: its shot (and its wait) is planned from this moment.
        return new BotConditions(game.noise(), hideFriction, own, game.clock());
    }
}
