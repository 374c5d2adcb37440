package minigolf.physics;

import java.util.Arrays;
import minigolf.terrain.Terrain;

/**
 * The ball as the game draws it, at frame times (multiples of dt), while the integrator's steps
 * follow their own lengths (docs/physics.md, "Step control"): a step may span several frames, and
 * frames never cut steps, so the game, the bots and the command line integrate exactly the same
 * steps. The stroke logs the state at the start of every piece of a step; the ball at a frame
 * time between two logged states follows the parabola that leaves the first with its velocity
 * and reaches the second (exact in drag-free flight, within a fraction of a millimetre rolling);
 * a rolling ball sits on the ground.
 */
final class FrameView {
    /** Values per logged state: t, x, y, z, vx, vy, vz, flying (1 or 0). */
    private static final int FIELDS = 8;

    private final Terrain terrain;
    private double[] log = new double[FIELDS * 8];
    private int count;
    /** The ball at the last frame shown. */
    double t, x, y, z, vx, vy, vz;
    boolean flying;

    FrameView(Terrain terrain) {
        this.terrain = terrain;
    }

    /** A new stroke: the view and the log start at the ball. */
    void start(BallState b) {
        count = 0;
        mark(b);
        t = b.t;
        x = b.x;
        y = b.y;
        z = b.z;
        vx = b.vx;
        vy = b.vy;
        vz = b.verticalSpeed();
        flying = b.flying;
    }

    /** Logs the ball's state as a piece of a step begins. */
    void mark(BallState b) {
        if (count > 0 && log[(count - 1) * FIELDS] == b.t) count--; // a piece that took no time
        int i = count * FIELDS;
        if (i + FIELDS > log.length) log = Arrays.copyOf(log, 2 * log.length);
        log[i] = b.t;
        log[i + 1] = b.x;
        log[i + 2] = b.y;
        log[i + 3] = b.z;
        log[i + 4] = b.vx;
        log[i + 5] = b.vy;
        log[i + 6] = b.verticalSpeed();
        log[i + 7] = b.flying ? 1 : 0;
        count++;
    }

    /** Shows the ended stroke: the ball at its end point, still. */
    void end(BallState b) {
        t = b.t;
        x = b.endX;
        y = b.endY;
        z = Double.isFinite(b.endZ) ? b.endZ : z;
        vx = vy = vz = 0;
        flying = false;
        count = 0;
    }

    /**
     * Shows the ball at {@code target}, which the integration has reached ({@code b.t >= target}):
     * between the last logged state at or before it and the next one (the ball's current state
     * closes the log). States before that one are dropped.
     */
    void show(double target, BallState b) {
        mark(b);
        int i = count - 1;
        while (i > 0 && log[i * FIELDS] > target) i--;
        int a = i * FIELDS;
        if (i == count - 1) {
            copy(a);
        } else {
            int e = a + FIELDS;
            double tau = log[e] - log[a], s = target - log[a];
            copy(a);
            t = target;
            double u = s / tau;
            // p(s) = p0 + v0 s + (p1 - p0 - v0 tau) (s/tau)^2: leaves p0 with v0, reaches p1 at tau.
            double cx = log[e + 1] - log[a + 1] - log[a + 4] * tau;
            double cy = log[e + 2] - log[a + 2] - log[a + 5] * tau;
            x = log[a + 1] + log[a + 4] * s + cx * u * u;
            y = log[a + 2] + log[a + 5] * s + cy * u * u;
            vx = log[a + 4] + 2 * cx * u / tau;
            vy = log[a + 5] + 2 * cy * u / tau;
            if (flying) {
                double cz = log[e + 3] - log[a + 3] - log[a + 6] * tau;
                z = log[a + 3] + log[a + 6] * s + cz * u * u;
                vz = log[a + 6] + 2 * cz * u / tau;
            } else {
                z = terrain.height(x, y);
                vz = vz + (log[e + 6] - vz) * u;
            }
        }
        // Keep the log from state i on (the step in progress).
        System.arraycopy(log, a, log, 0, (count - i) * FIELDS);
        count -= i;
        count--; // the ball's current state is logged again when the next piece begins
    }

    private void copy(int a) {
        t = log[a];
        x = log[a + 1];
        y = log[a + 2];
        z = log[a + 3];
        vx = log[a + 4];
        vy = log[a + 5];
        vz = log[a + 6];
        flying = log[a + 7] != 0;
    }
}
