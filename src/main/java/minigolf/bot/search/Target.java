package minigolf.bot.search;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;

/**
 * What a search aims at from the ball: the hole (success = holed) or a waypoint (success = rest
 * within {@code tolerance}). The miss vector is rest point (or water entry) minus target.
 */
public record Target(double ballX, double ballY, double x, double y, boolean hole, double tolerance) {
    public static Target hole(CountingSimulator sim, double ballX, double ballY) {
        var h = sim.world().hole();
        return new Target(ballX, ballY, h.position().x(), h.position().y(), true, h.radius());
    }

    public static Target point(double ballX, double ballY, double x, double y, double tolerance) {
        return new Target(ballX, ballY, x, y, false, tolerance);
    }

    public boolean reached(ShotResult r) {
        if (hole) return r.outcome() == Outcome.HOLED;
        return r.outcome() == Outcome.STOPPED && Math.hypot(r.endX() - x, r.endY() - y) <= tolerance;
    }

    public double distance() {
        return Math.hypot(x - ballX, y - ballY);
    }

    public double angle() {
        return Math.atan2(y - ballY, x - ballX);
    }

    /** The shot's miss, written into out[0..1]; a penalty counts where the ball was lost. */
    public void miss(ShotResult r, double[] out) {
        out[0] = r.endX() - x;
        out[1] = r.endY() - y;
    }

    /** Miss distance, with lost balls ranked behind every ball on the course. */
    public double cost(ShotResult r) {
        if (reached(r)) return 0;
        double d = Math.hypot(r.endX() - x, r.endY() - y);
        return r.outcome().isPenalty() ? 100 + d : d;
    }

    public ShotResult simulate(CountingSimulator sim, Shot shot) {
        return sim.simulate(ballX, ballY, shot);
    }
}
