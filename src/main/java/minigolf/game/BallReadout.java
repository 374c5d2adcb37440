package minigolf.game;

import minigolf.physics.World;

/**
 * What the HUD shows about the ball: position (z = h, the contact point), velocity, acceleration,
 * the slope under it (|grad h| and its angle in degrees) and the friction there.
 */
public record BallReadout(double x, double y, double z, double vx, double vy, double ax, double ay,
                          double slope, double slopeDegrees, double kineticFriction, double staticFriction) {
    public static BallReadout of(World world, double x, double y, double vx, double vy, double ax, double ay) {
        double[] s = new double[3];
        world.terrain().sample(x, y, s);
        double slope = Math.hypot(s[1], s[2]);
        return new BallReadout(x, y, s[0], vx, vy, ax, ay, slope, Math.toDegrees(Math.atan(slope)),
                world.friction().kinetic(x, y), world.friction().staticFriction(x, y));
    }

    public double speed() {
        return Math.hypot(vx, vy);
    }

    public double acceleration() {
        return Math.hypot(ax, ay);
    }
}
