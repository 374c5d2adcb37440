package minigolf.bot.play;

import minigolf.bot.Bot;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.course.Obstacle;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * Any bot on a course with moving obstacles (issue 24): the shot gains a wait before it is played,
 * which this bot chooses. It asks the bot it wraps for its shot at the moment of the request and,
 * unless that shot holes, at {@link #MOMENTS} - 1 later moments spread over the longest period of
 * the course's motions (they repeat); each candidate is simulated once more at its moment, and the
 * one that holes first (else the one whose ball ends nearest the hole, a penalty counting as far) is
 * played after its wait. On a course where nothing moves it is the wrapped bot, unchanged.
 */
public final class TimedBot implements Bot {
    /** Moments of a period a bot is asked for its shot at. */
    public static final int MOMENTS = 8;
    /** A penalty's score: further than any rest point. */
    private static final double PENALTY = 1e6;

    private final Bot inner;

    public TimedBot(Bot inner) {
        this.inner = inner;
    }

    /** The bot for this world: wrapped where obstacles move. */
    public static Bot forWorld(Bot bot, World world) {
        return world.moving() == null || bot instanceof TimedBot ? bot : new TimedBot(bot);
    }

    @Override
    public String name() {
        return inner.name();
    }

    @Override
    public Shot nextShot(BotRequest request) {
        World world = request.world();
        if (world.moving() == null) return inner.nextShot(request);
        double period = longestPeriod(world);
        CountingSimulator sim = request.simulator();
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        Shot best = null;
        double bestScore = Double.POSITIVE_INFINITY;
        for (int k = 0; k < MOMENTS; k++) {
            double wait = period * k / MOMENTS;
            double at = request.clock() + wait;
            sim.setClock(at);
            Shot shot;
            try {
                shot = inner.nextShot(request.at(at));
            } catch (minigolf.bot.BudgetExhaustedException e) {
                if (best != null) break;
                throw e;
            }
            if (shot == null) continue;
            Shot played = sim.limit(shot).withWait(0);
            ShotResult r;
            try {
                r = sim.simulate(request.ballX(), request.ballY(), played);
            } catch (minigolf.bot.BudgetExhaustedException e) {
                if (best == null) best = played.withWait(wait);
                break;
            }
            double score = r.outcome() == Outcome.HOLED ? -1
                    : r.outcome().isPenalty() || r.outcome() == Outcome.TIMEOUT ? PENALTY
                    : Math.hypot(r.endX() - hx, r.endY() - hy);
            if (score < bestScore) {
                bestScore = score;
                best = played.withWait(wait);
            }
            if (score < 0) break;
        }
        sim.setClock(request.clock());
        return best;
    }

    /** The longest period of the course's motions (s). */
    static double longestPeriod(World world) {
        double period = 0;
        for (Obstacle o : world.course().obstacles()) {
            if (o instanceof Obstacle.Moving m) period = Math.max(period, m.motion().period());
        }
        return period;
    }
}
