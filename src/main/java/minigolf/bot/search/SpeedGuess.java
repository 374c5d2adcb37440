package minigolf.bot.search;

import minigolf.physics.World;

/**
 * The bots' one physics estimate of speed and roll, from the energy on a plane through the two
 * points: v^2 / 2 = g (mu_k L + h_target - h_ball), with mu_k where the ball lies. Exact on flat
 * ground with one friction (a 5 m/s putt at mu_k 0.1 rolls 12.7421 m); elsewhere a first guess
 * that the searches correct by simulation.
 */
public final class SpeedGuess {
    /** Friction below this is taken as this in {@link #roll}: a frictionless roll never ends. */
    public static final double MIN_FRICTION = 1e-3;

    private SpeedGuess() {
    }

    /** v^2 = 2 g (mu L + rise): the squared speed that rolls {@code length} metres up {@code rise}. */
    public static double speedSquared(double gravity, double mu, double length, double rise) {
        return 2 * gravity * (mu * length + rise);
    }

    /** How far a ball at {@code speed} rolls while dropping {@code drop}: v^2 / (2 g mu) + drop / mu. */
    public static double roll(double gravity, double mu, double speed, double drop) {
        return speed * speed / (2 * gravity * mu) + drop / mu;
    }

    /**
     * The speed that stops a ball from (x, y), rolling {@code length} metres, at the height of
     * (tx, ty); never below sqrt({@code minSpeedSquared}) (a shot that stays put finds nothing).
     */
    public static double speed(World world, double x, double y, double length, double tx, double ty,
                               double minSpeedSquared) {
        double mu = world.friction().kinetic(x, y);
        double rise = world.terrain().height(tx, ty) - world.terrain().height(x, y);
        double g = world.physics().gravity();
        // Push zones and magnets on the straight way give (or take) energy, as a drop (or rise) of the ground.
        if (world.forces() != null) rise -= forceWork(world, x, y, tx, ty) / g;
        return Math.sqrt(Math.max(speedSquared(g, mu, length, rise), minSpeedSquared));
    }

    /** The work per unit mass of the push zones and magnets along the straight way (16 pieces). */
    static double forceWork(World world, double x, double y, double tx, double ty) {
        double[] f = new double[2];
        double work = 0;
        int pieces = 16;
        for (int k = 0; k < pieces; k++) {
            double s = (k + 0.5) / pieces;
            world.forces().force(x + s * (tx - x), y + s * (ty - y), f);
            work += (f[0] * (tx - x) + f[1] * (ty - y)) / pieces;
        }
        return work;
    }

    /** How far a maximum-speed shot from (x, y) rolls towards a point at the height of (tx, ty). */
    public static double maxRoll(World world, double x, double y, double tx, double ty) {
        double mu = Math.max(world.friction().kinetic(x, y), MIN_FRICTION);
        double drop = world.terrain().height(x, y) - world.terrain().height(tx, ty);
        return roll(world.physics().gravity(), mu, world.physics().maxSpeed(), drop);
    }
}
