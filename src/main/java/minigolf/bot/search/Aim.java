package minigolf.bot.search;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/**
 * The simplest aiming: shoot at the target with the physics speed guess, then correct the angle
 * by the angular miss and the speed by sqrt(wanted / travelled distance), a few times. Used by the
 * path bots to reach waypoints.
 */
public final class Aim {
    private Aim() {
    }

    /** The shot chosen and whether it reached the target. */
    public record Aimed(Shot shot, boolean reached) {
    }

    /** The shot that reached the target, or the one that came nearest (lost balls last). */
    public static Aimed at(CountingSimulator sim, Target target, int maxShots) {
        double angle = target.angle();
        double speed = SpeedGuess.speed(sim.world(), target.ballX(), target.ballY(), target.distance(), target.x(),
                target.y(), 0.01);
        Shot best = null;
        double bestCost = Double.POSITIVE_INFINITY;
        for (int i = 0; i < maxShots; i++) {
            Shot shot = sim.limit(Shot.polar(angle, speed));
            ShotResult r = target.simulate(sim, shot);
            if (target.reached(r)) return new Aimed(shot, true);
            double cost = target.cost(r);
            if (cost < bestCost) {
                bestCost = cost;
                best = shot;
            }
            if (r.outcome().isPenalty()) {
                speed *= 0.85;
                continue;
            }
            double ex = r.endX() - target.ballX(), ey = r.endY() - target.ballY();
            double travelled = Math.hypot(ex, ey);
            if (travelled > 1e-3) angle += Math.IEEEremainder(target.angle() - Math.atan2(ey, ex), 2 * Math.PI);
            speed = Math.min(speed * Math.sqrt(target.distance() / Math.max(travelled, 0.05)), sim.maxSpeed());
        }
        return best == null ? null : new Aimed(best, false);
    }
}
