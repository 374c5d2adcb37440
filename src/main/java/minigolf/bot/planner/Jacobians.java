package minigolf.bot.planner;

import minigolf.bot.Shot;

/**
 * The planner's first guesses of how the rest point moves with the shot's velocity, as 2 x 2
 * matrices {d restX/d vx, d restX/d vy, d restY/d vx, d restY/d vy} (Broyden starts from them).
 */
final class Jacobians {
    private Jacobians() {
    }

    /** J mirrored in the line with unit normal n: (I - 2 n n^T) J (after a bounce off that line). */
    static double[] reflected(double[] j, double nx, double ny) {
        double r00 = 1 - 2 * nx * nx, r01 = -2 * nx * ny, r11 = 1 - 2 * ny * ny;
        return new double[] {
            r00 * j[0] + r01 * j[2], r00 * j[1] + r01 * j[3],
            r01 * j[0] + r11 * j[2], r01 * j[1] + r11 * j[3]
        };
    }

    /**
     * On flat ground the roll L grows with the speed squared: dL/ds = 2L/s along the shot, and a
     * turn by da moves the rest point L da = (L/s) (s da) across it. (dx, dy): rest point minus
     * ball (at least 0.1 m is assumed).
     */
    static double[] flat(Shot shot, double dx, double dy) {
        double s = Math.max(shot.speed(), 1e-3);
        double ux = shot.vx() / s, uy = shot.vy() / s;
        double length = Math.max(Math.hypot(dx, dy), 0.1);
        double along = 2 * length / s, across = length / s;
        return new double[] {
            along * ux * ux + across * uy * uy, (along - across) * ux * uy,
            (along - across) * ux * uy, along * uy * uy + across * ux * ux
        };
    }
}
