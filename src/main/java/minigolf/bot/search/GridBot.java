package minigolf.bot.search;

import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/**
 * {@code grid}, the seed's single-shot bot: find the flag, scan velocities around its direction
 * up to the maximum speed at a fixed angle step and speed step, keep the successful ones and shoot
 * the best (the one resting nearest the centre); when none succeeds (an obstacle or water in the
 * way), widen the angle and scan the new directions. Without any success it plays the shot that
 * ended nearest the hole.
 */
public final class GridBot extends SearchBot {
    private final double angleStep;
    private final double speedStep;
    private final double initialHalfWidth;

    /** Defaults: 1 degree, 0.05 m/s, +-10 degrees first. */
    public GridBot() {
        this(Math.toRadians(1), 0.05, Math.toRadians(10));
    }

    public GridBot(double angleStep, double speedStep, double initialHalfWidth) {
        this.angleStep = angleStep;
        this.speedStep = speedStep;
        this.initialHalfWidth = initialHalfWidth;
    }

    @Override
    public String name() {
        return "grid";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        Target target = Target.hole(sim, request.ballX(), request.ballY());
        double centre = target.angle();
        int speeds = (int) Math.floor(sim.maxSpeed() / speedStep);
        int scanned = -1;
        for (double halfWidth = initialHalfWidth; ; halfWidth *= 2) {
            sim.phase("scan +-" + Math.round(Math.toDegrees(Math.min(halfWidth, Math.PI))) + " deg");
            int steps = (int) Math.floor(Math.min(halfWidth, Math.PI) / angleStep);
            Shot best = null;
            double bestMiss = Double.POSITIVE_INFINITY;
            for (int k = -steps; k <= steps; k++) {
                if (Math.abs(k) <= scanned) continue;
                if (k * angleStep >= Math.PI) continue;
                double angle = centre + k * angleStep;
                for (int s = 1; s <= speeds; s++) {
                    Shot shot = Shot.polar(angle, s * speedStep);
                    ShotResult r = target.simulate(sim, shot);
                    if (!target.reached(r)) continue;
                    double miss = Math.hypot(r.endX() - target.x(), r.endY() - target.y());
                    if (miss < bestMiss) {
                        bestMiss = miss;
                        best = shot;
                    }
                }
            }
            if (best != null) return best;
            scanned = steps;
            if (halfWidth >= Math.PI) break;
        }
        Shot fallback = sim.bestShot();
        return fallback != null ? fallback : directGuess(request.world(), request.ballX(), request.ballY());
    }
}
