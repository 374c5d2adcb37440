package minigolf.bot.level;

import java.util.SplittableRandom;
import minigolf.bot.Bot;
import minigolf.bot.BotRequest;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.noise.HumanError;
import minigolf.bot.noise.RobustBot;
import minigolf.bot.planner.PlannerBot;

/**
 * A {@link Level} as a bot: its strategy chooses a shot, then its {@link HumanError} is drawn from
 * the request's seed and the shot comes back as the level plays it (so the game, {@code solve} and
 * {@code experiment} play the error without knowing of it, and the same request gives the same shot).
 *
 * <p>A player whose hole goes badly takes more care: from stroke {@link #CAREFUL_FROM} on (penalties
 * included) the error halves with every stroke, so the level soon plays like the planner and holes
 * out within the game's limit of 10 strokes (a bound on the tail, not a guarantee; every game
 * measured in docs/bots.md holed within it).
 */
public final class LevelBot implements Bot {
    /** The stroke (0-based, penalties included) from which the error halves with every stroke. */
    static final int CAREFUL_FROM = 5;
    /** The speed at which the robust strategy sizes its noise model ({@link HumanError#asNoiseModel}), m/s. */
    static final double PLANNING_SPEED = 2.0;
    /** Mixed into the request's seed for the error's draws, so the strategy keeps the request's own seed. */
    private static final long ERROR_SALT = 0x4C6576656C2D3233L;

    private final String name;
    private final HumanError error;
    private final boolean robust;
    private final Bot strategy;

    public LevelBot(Level level) {
        this(level.id(), level.error(), level.robust());
    }

    /** A level of one's own (calibration tools try candidates): see {@link Level} for the parts. */
    public LevelBot(String name, HumanError error, boolean robust) {
        this.name = name;
        this.error = error;
        this.robust = robust;
        this.strategy = robust ? new RobustBot() : new PlannerBot();
    }

    @Override
    public String name() {
        return name;
    }

    /** The error on a stroke after {@code strokesTaken} strokes: the level's, halved per stroke from {@link #CAREFUL_FROM}. */
    public HumanError errorAfter(int strokesTaken) {
        int careful = Math.max(0, strokesTaken - CAREFUL_FROM + 1);
        return careful == 0 ? error : error.times(Math.pow(0.5, careful));
    }

    @Override
    public Shot nextShot(BotRequest request) {
        BotRequest planned = request;
        if (robust) {
            // The robust bot plans for the level's own error on top of any noise the game adds.
            NoiseModel own = error.asNoiseModel(PLANNING_SPEED), game = request.noise();
            planned = new BotRequest(request.simulator(), request.ballX(), request.ballY(), request.strokesTaken(),
                    request.seed(), new NoiseModel(game.position(), Math.hypot(game.velocity(), own.velocity())));
        }
        Shot chosen = request.simulator().limit(strategy.nextShot(planned));
        return errorAfter(request.strokesTaken()).play(chosen, new SplittableRandom(request.seed() ^ ERROR_SALT),
                request.world().physics().maxSpeed());
    }
}
