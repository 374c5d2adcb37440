package minigolf.bot.search;

import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/**
 * {@code local}, the seed's local search with the geometric heuristic: start on the ball-hole
 * line; after each shot turn the aim towards the side of the miss the hole is on, with a step that
 * shrinks whenever the side flips; raise the power by 1.2 when short (and lower it when long, by a
 * factor that shrinks the same way); when a start stalls, restart at the next power level.
 */
public final class LocalSearchBot extends SearchBot {
    private final double[] powerLevels;
    private final double initialAngleStep;
    private final int iterationsPerStart;

    /** Defaults: power levels 40..100% of max speed, 8 degree first step, 40 shots per start. */
    public LocalSearchBot() {
        this(new double[] {0.4, 0.55, 0.7, 0.85, 1.0, 0.25}, Math.toRadians(8), 40);
    }

    public LocalSearchBot(double[] powerLevels, double initialAngleStep, int iterationsPerStart) {
        this.powerLevels = powerLevels.clone();
        this.initialAngleStep = initialAngleStep;
        this.iterationsPerStart = iterationsPerStart;
    }

    @Override
    public String name() {
        return "local";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        Target target = Target.hole(sim, request.ballX(), request.ballY());
        double holeDistance = target.distance();
        for (double level : powerLevels) {
            sim.phase("power " + Math.round(level * 100) + "%");
            double angle = target.angle();
            double speed = level * sim.maxSpeed();
            double angleStep = initialAngleStep;
            double powerFactor = 1.2;
            int lastSide = 0, lastLength = 0;
            for (int i = 0; i < iterationsPerStart; i++) {
                Shot shot = sim.limit(Shot.polar(angle, speed));
                ShotResult r = target.simulate(sim, shot);
                if (target.reached(r)) return shot;
                double ex = r.endX() - target.ballX(), ey = r.endY() - target.ballY();
                double hx = target.x() - target.ballX(), hy = target.y() - target.ballY();
                // Which side of the ball's line (ball to rest point) the hole lies on.
                double cross = ex * hy - ey * hx;
                int side = cross > 0 ? 1 : -1;
                if (lastSide != 0 && side != lastSide) angleStep *= 0.5;
                lastSide = side;
                double travelled = Math.hypot(ex, ey);
                int length = r.outcome().isPenalty() ? 0 : (travelled < holeDistance ? -1 : 1);
                if (lastLength != 0 && length != 0 && length != lastLength) powerFactor = 1 + (powerFactor - 1) * 0.5;
                if (length != 0) lastLength = length;
                double miss = Math.hypot(r.endX() - target.x(), r.endY() - target.y());
                angle += side * Math.min(angleStep, Math.atan2(miss, Math.max(holeDistance, 1e-6)) + 1e-4);
                if (length < 0) speed = Math.min(speed * powerFactor, sim.maxSpeed());
                else if (length > 0) speed /= powerFactor;
                if (angleStep < 1e-6 && powerFactor < 1 + 1e-6) break;
            }
        }
        Shot fallback = sim.bestShot();
        return fallback != null ? fallback : directGuess(request.world(), request.ballX(), request.ballY());
    }
}
