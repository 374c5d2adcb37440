package minigolf.bot.level;

import java.util.SplittableRandom;
import minigolf.bot.Bot;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.noise.HumanError;
import minigolf.bot.noise.RobustBot;
import minigolf.bot.planner.PlannerBot;
import minigolf.physics.ShotResult;

/**
 * A {@link Level} as a bot: its strategy chooses a shot, then its {@link HumanError} is drawn from
 * the request's seed and the shot comes back as the level plays it (so the game, {@code solve} and
 * {@code experiment} play the error without knowing of it, and the same request gives the same shot).
 *
 * <p>The error may depend on the shot: an attempt at a hole in one (a hole's first stroke that
 * would hole as chosen) is struck with the level's {@link Level#aceError()} ({@code hard} goes for
 * aces like {@code medium} but plays its other strokes nearly exactly).
 *
 * <p>A player whose hole goes badly takes more care ({@link Care}): from a stroke on (penalties
 * included) the error shrinks with every stroke, and a level may then also lay up like the robust
 * bot, so it soon plays like the planner and holes out within the game's limit of 10 strokes (a
 * bound on the tail, not a guarantee; docs/bots.md has the games measured).
 */
public final class LevelBot implements Bot {
    /**
     * How a level takes care once its hole goes badly: from stroke {@code from} (0-based, penalties
     * included) its error is multiplied by {@code shrink} with every stroke, and with {@code layUp}
     * it plans for that stroke's error as the robust bot does, laying up where its line would likely
     * miss (a lay-up beside water that only an exact stroke keeps dry sent one game in three times).
     */
    public record Care(int from, double shrink, boolean layUp) {
        /** From the sixth stroke the error halves per stroke; the line stays the strategy's own. */
        public static final Care HALVING_FROM_SIXTH = new Care(5, 0.5, false);

        public Care {
            if (from < 0 || !(shrink > 0 && shrink <= 1)) throw new IllegalArgumentException("care from stroke " + from
                    + ", shrink " + shrink + " (must be >= 0 and in (0, 1])");
        }
    }
    /** The speed at which the robust strategy sizes its noise model ({@link HumanError#asNoiseModel}), m/s. */
    static final double PLANNING_SPEED = 2.0;
    /** Mixed into the request's seed for the error's draws, so the strategy keeps the request's own seed. */
    static final long ERROR_SALT = 0x4C6576656C2D3233L;

    private final String name;
    private final HumanError error;
    private final HumanError aceError;
    private final boolean robust;
    private final Care care;
    private final Bot strategy;

    public LevelBot(Level level) {
        this(level.id(), level.error(), level.aceError(), level.robust(), level.care());
    }

    /** A level of one's own with one error for every stroke: see {@link Level} for the parts. */
    public LevelBot(String name, HumanError error, boolean robust) {
        this(name, error, error, robust);
    }

    /** A level of one's own (calibration tools try candidates): see {@link Level} for the parts. */
    public LevelBot(String name, HumanError error, HumanError aceError, boolean robust) {
        this(name, error, aceError, robust, Care.HALVING_FROM_SIXTH);
    }

    /** A level of one's own with its own care (calibration tools try candidates): see {@link Level} for the parts. */
    public LevelBot(String name, HumanError error, HumanError aceError, boolean robust, Care care) {
        this.name = name;
        this.error = error;
        this.aceError = aceError;
        this.robust = robust;
        this.care = care;
        // Without noise to plan for, the robust bot plays its planner's shot: one planner (and its
        // memory of the hole) before and after the level lays up.
        this.strategy = robust || care.layUp() ? new RobustBot() : new PlannerBot();
    }

    @Override
    public String name() {
        return name;
    }

    /** The error on a stroke after {@code strokesTaken} strokes: the level's, shrinking per stroke from its care's stroke on. */
    public HumanError errorAfter(int strokesTaken) {
        int careful = Math.max(0, strokesTaken - care.from() + 1);
        return careful == 0 ? error : error.times(Math.pow(care.shrink(), careful));
    }

    @Override
    public Shot nextShot(BotRequest request) {
        BotRequest planned = request;
        boolean layingUp = !robust && care.layUp() && request.strokesTaken() >= care.from();
        if (robust || layingUp) {
            // The robust bot plans for the level's own error on top of any noise the game adds: the
            // full error, or once careful the error of this stroke (planned for the full one, a
            // careful player laid up beside the cup instead of holing a 1 m putt).
            NoiseModel own = (layingUp ? errorAfter(request.strokesTaken()) : error).asNoiseModel(PLANNING_SPEED);
            NoiseModel game = request.noise();
            planned = new BotRequest(request.simulator(), request.ballX(), request.ballY(), request.strokesTaken(),
                    request.seed(), new NoiseModel(game.position(), Math.hypot(game.velocity(), own.velocity())), request.clock());
        }
        Shot chosen = request.simulator().limit(strategy.nextShot(planned));
        HumanError now = aceAttempt(request, chosen) ? aceError : errorAfter(request.strokesTaken());
        return now.play(chosen, new SplittableRandom(request.seed() ^ ERROR_SALT), request.world().physics().maxSpeed());
    }

    /**
     * Whether {@code chosen} is an attempt at a hole in one: the hole's first stroke, and the shot
     * as chosen holes. Its result is usually known from the strategy's own search
     * ({@link CountingSimulator#knownResult}); else it is simulated once, if the budget and the
     * time allow (when they do not, the stroke counts as no attempt).
     */
    private boolean aceAttempt(BotRequest request, Shot chosen) {
        if (request.strokesTaken() != 0 || aceError.equals(error)) return false;
        CountingSimulator sim = request.simulator();
        ShotResult known = sim.knownResult(chosen);
        if (known != null) return CountingSimulator.holed(known);
        try {
            return sim.remaining() > 0 && CountingSimulator.holed(sim.simulate(request.ballX(), request.ballY(), chosen));
        } catch (BudgetExhaustedException e) {
            return false;
        }
    }
}
