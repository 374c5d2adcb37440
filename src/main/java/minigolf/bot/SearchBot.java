package minigolf.bot;

import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * The shared frame of every bot: it opens the best-shot memory, runs the bot's search and, when
 * the budget runs out mid-search, returns the best shot seen (or, with nothing simulated at all,
 * the physics guess straight at the hole).
 */
public abstract class SearchBot implements Bot {
    @Override
    public final Shot nextShot(BotRequest request) {
        CountingSimulator sim = request.simulator();
        sim.checkCancelled();
        sim.beginShot(request.ballX(), request.ballY(), scoreFor(request));
        try {
            return sim.limit(search(request));
        } catch (BudgetExhaustedException e) {
            Shot best = sim.bestShot();
            return best != null ? best : sim.limit(directGuess(request.world(), request.ballX(), request.ballY()));
        }
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
        double g = world.physics().gravity();
        double mu = world.friction().kinetic(x, y);
        double rise = world.terrain().height(hx, hy) - world.terrain().height(x, y);
        double speedSquared = 2 * g * (mu * distance + rise);
        double speed = Math.min(Math.sqrt(Math.max(speedSquared, 0.01)), world.physics().maxSpeed());
        double angle = Math.atan2(dy, dx);
        return Shot.polar(angle, speed);
    }
}
