package minigolf.bot.search;

import java.util.SplittableRandom;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/**
 * Particle swarm over the velocity (vx, vy), cost = miss distance (a lost ball ranks behind every
 * ball on the course). Defaults as the seed: inertia 0.25, cognitive 0.5, social 1.0, inertia
 * damped by 0.99 per generation, 12 particles.
 */
public final class SwarmSolver {
    private final double inertia, cognitive, social, damping;
    private final int particles, generations;

    public SwarmSolver() {
        this(0.25, 0.5, 1.0, 0.99, 12, 150);
    }

    public SwarmSolver(double inertia, double cognitive, double social, double damping, int particles, int generations) {
        this.inertia = inertia;
        this.cognitive = cognitive;
        this.social = social;
        this.damping = damping;
        this.particles = particles;
        this.generations = generations;
    }

    /**
     * A shot that reaches the target, or null. Particles start around {@code centre} (within
     * {@code angleSpread} radians and {@code speedSpread} of its speed, as a fraction), or
     * uniformly towards the target's half-plane when centre is null.
     */
    public Shot solve(CountingSimulator sim, Target target, Shot centre, double angleSpread, double speedSpread,
                      SplittableRandom random) {
        double vmax = sim.maxSpeed();
        double[][] x = new double[particles][2], v = new double[particles][2], best = new double[particles][2];
        double[] bestCost = new double[particles];
        double[] global = new double[2];
        double globalCost = Double.POSITIVE_INFINITY;
        for (int p = 0; p < particles; p++) {
            double angle, speed;
            if (centre != null) {
                angle = Math.atan2(centre.vy(), centre.vx()) + angleSpread * (2 * random.nextDouble() - 1);
                speed = centre.speed() * (1 + speedSpread * (2 * random.nextDouble() - 1));
            } else {
                angle = target.angle() + (Math.PI / 2) * (2 * random.nextDouble() - 1);
                speed = vmax * random.nextDouble();
            }
            speed = Math.min(Math.max(speed, 0.01), vmax);
            x[p][0] = speed * Math.cos(angle);
            x[p][1] = speed * Math.sin(angle);
            v[p][0] = 0.1 * vmax * (2 * random.nextDouble() - 1);
            v[p][1] = 0.1 * vmax * (2 * random.nextDouble() - 1);
            bestCost[p] = Double.POSITIVE_INFINITY;
        }
        double w = inertia;
        for (int g = 0; g < generations; g++) {
            for (int p = 0; p < particles; p++) {
                Shot shot = sim.limit(Shot.of(x[p][0], x[p][1]));
                ShotResult r = target.simulate(sim, shot);
                if (target.reached(r)) return shot;
                double cost = target.cost(r);
                if (cost < bestCost[p]) {
                    bestCost[p] = cost;
                    best[p][0] = shot.vx();
                    best[p][1] = shot.vy();
                }
                if (cost < globalCost) {
                    globalCost = cost;
                    global[0] = shot.vx();
                    global[1] = shot.vy();
                }
            }
            for (int p = 0; p < particles; p++) {
                for (int d = 0; d < 2; d++) {
                    v[p][d] = w * v[p][d] + cognitive * random.nextDouble() * (best[p][d] - x[p][d])
                            + social * random.nextDouble() * (global[d] - x[p][d]);
                    x[p][d] += v[p][d];
                }
                double s = Math.hypot(x[p][0], x[p][1]);
                if (s > vmax) {
                    x[p][0] *= vmax / s;
                    x[p][1] *= vmax / s;
                }
            }
            w *= damping;
        }
        return null;
    }
}
