package minigolf.bot.search;

import minigolf.bot.Bot;
import minigolf.bot.BotCancelledException;
import minigolf.bot.BotRequest;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseMaps;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * The shared frame of every bot: it opens the best-shot memory, runs the bot's search and, when
 * the budget or the time limit runs out mid-search, returns the best shot seen (or, with nothing
 * simulated at all, the physics guess straight at the hole). A bot always answers: should its
 * search fail with any other exception (a bug), the error is recorded in the simulator
 * ({@link CountingSimulator#errors()}, which the tests check is empty) and the best shot so far is
 * played; only a cancel leaves {@link #nextShot}.
 *
 * <p>Where no path along the ground reaches the hole (a green ringed by water, a hole inside low
 * walls) no putt can hole out, so every search bot plays through the air there
 * ({@link ChipSearch}), unless it plans its own chips ({@link #chipsWhenCutOff()}) or whoever plays
 * the shot can only putt.
 */
public abstract class SearchBot implements Bot {
    /**
     * The course's grid and distance field to the hole (plain, built once per world): whether the
     * ball is cut off from the hole along the ground, and the routes of the bots that follow one.
     */
    private final CourseMaps maps = new CourseMaps();

    @Override
    public final Shot nextShot(BotRequest request) {
        CountingSimulator sim = request.simulator();
        if (request.token().isCancelled()) throw new BotCancelledException();
        try {
            sim.beginShot(request.ballX(), request.ballY(), null);
            sim.beginShot(request.ballX(), request.ballY(), scoreFor(request));
            Shot air = chipWhenCutOff(request);
            return sim.limit(air != null ? air : search(request));
        } catch (BudgetExhaustedException e) {
            return fallback(request);
        } catch (BotCancelledException e) {
            throw e;
        } catch (RuntimeException e) {
            sim.recordError(name() + ": " + e);
            if (request.token().isCancelled()) throw new BotCancelledException();
            return fallback(request);
        }
    }

    private static Shot fallback(BotRequest request) {
        CountingSimulator sim = request.simulator();
        Shot best = sim.bestShot();
        return best != null ? best : sim.limit(directGuess(request.world(), request.ballX(), request.ballY()));
    }

    /** Whether this bot leaves chips where the ground is cut off to {@link ChipSearch}; the planner plans its own. */
    protected boolean chipsWhenCutOff() {
        return true;
    }

    private Shot chipWhenCutOff(BotRequest request) {
        CountingSimulator sim = request.simulator();
        if (!chipsWhenCutOff() || sim.puttsOnly()) return null;
        CourseMaps m = maps(request);
        if (!ChipSearch.cutOff(m.toHole(), request.ballX(), request.ballY())) return null;
        sim.phase("chip");
        return new ChipSearch(sim, m.grid(), m.toHole(), request.ballX(), request.ballY()).search();
    }

    /** The course's plain grid and distance field for the request's world (built on first use, then kept). */
    protected final CourseMaps maps(BotRequest request) {
        maps.prepare(request.world(), request.token());
        return maps;
    }

    /** Finds the shot; may throw BudgetExhaustedException (handled) or BotCancelledException (passed on). */
    protected abstract Shot search(BotRequest request);

    /** How the fallback ranks shots: by default holed first, then straight-line distance, penalties last. */
    protected CountingSimulator.ShotScore scoreFor(BotRequest request) {
        World world = request.world();
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        return r -> straightScore(r, hx, hy);
    }

    static double straightScore(ShotResult r, double hx, double hy) {
        if (r.outcome() == Outcome.HOLED) return -1;
        if (r.outcome().isPenalty()) return 1e9;
        return Math.hypot(r.endX() - hx, r.endY() - hy);
    }

    /**
     * Straight at the hole at the speed that stops the ball there on a plane through both points:
     * v^2 / 2 = g (mu_k L + h_hole - h_ball). A physics estimate, not a simulation.
     */
    public static Shot directGuess(World world, double x, double y) {
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        double dx = hx - x, dy = hy - y;
        double distance = Math.hypot(dx, dy);
        double speed = Math.min(SpeedGuess.speed(world, x, y, distance, hx, hy, 0.01), world.physics().maxSpeed());
        double angle = Math.atan2(dy, dx);
        return Shot.polar(angle, speed);
    }
}
