package minigolf.bot.search;

import java.util.SplittableRandom;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/**
 * Newton-Raphson on the miss vector F(v) = end point - target, the Jacobian by central finite
 * differences (4 simulations per iteration). A step that would exceed the speed limit is halved
 * until it does not; when the iteration stalls (no progress, a singular Jacobian) it restarts from
 * a random guess near the start. Water makes F discontinuous, and then it usually fails: that is
 * the seed's behaviour, reported as such.
 */
public final class NewtonSolver {
    private final double step;
    private final int iterations;
    private final int restarts;

    /** Defaults: h = 1e-4 m/s, 25 iterations per start, 8 restarts. */
    public NewtonSolver() {
        this(1e-4, 25, 8);
    }

    public NewtonSolver(double step, int iterations, int restarts) {
        this.step = step;
        this.iterations = iterations;
        this.restarts = restarts;
    }

    /** A shot that reaches the target, or null. */
    public Shot solve(CountingSimulator sim, Target target, Shot start, SplittableRandom random) {
        Shot seed = start;
        double[] f = new double[2], fp = new double[2], fm = new double[2];
        for (int attempt = 0; attempt <= restarts; attempt++) {
            Shot v = sim.limit(seed);
            double previousMiss = Double.POSITIVE_INFINITY;
            for (int i = 0; i < iterations; i++) {
                ShotResult r = target.simulate(sim, v);
                if (target.reached(r)) return v;
                target.miss(r, f);
                double miss = Math.hypot(f[0], f[1]);
                if (miss >= previousMiss * 0.999) break;
                previousMiss = miss;
                double[] j = new double[4];
                for (int axis = 0; axis < 2; axis++) {
                    Shot plus = axis == 0 ? Shot.of(v.vx() + step, v.vy()) : Shot.of(v.vx(), v.vy() + step);
                    Shot minus = axis == 0 ? Shot.of(v.vx() - step, v.vy()) : Shot.of(v.vx(), v.vy() - step);
                    target.miss(target.simulate(sim, plus), fp);
                    target.miss(target.simulate(sim, minus), fm);
                    j[axis] = (fp[0] - fm[0]) / (2 * step);
                    j[2 + axis] = (fp[1] - fm[1]) / (2 * step);
                }
                double det = j[0] * j[3] - j[1] * j[2];
                if (!(Math.abs(det) > 1e-12) || !Double.isFinite(det)) break;
                double dx = -(j[3] * f[0] - j[1] * f[1]) / det;
                double dy = -(-j[2] * f[0] + j[0] * f[1]) / det;
                double nx = v.vx() + dx, ny = v.vy() + dy;
                for (int h = 0; h < 30 && Math.hypot(nx, ny) > sim.maxSpeed(); h++) {
                    dx *= 0.5;
                    dy *= 0.5;
                    nx = v.vx() + dx;
                    ny = v.vy() + dy;
                }
                v = sim.limit(Shot.of(nx, ny));
            }
            // Stationary: a nearby guess (+-10 degrees, +-20% speed).
            double angle = Math.atan2(start.vy(), start.vx()) + Math.toRadians(10) * (2 * random.nextDouble() - 1);
            double speed = start.speed() * (1 + 0.2 * (2 * random.nextDouble() - 1));
            seed = Shot.polar(angle, speed);
        }
        return null;
    }
}
