package minigolf.physics;

import java.util.List;
import minigolf.terrain.Terrain;

/**
 * What a stroke tells the world: each state to the {@link TrajectoryListener} (and, for a listener
 * that wants detail, states along a long step's path), each event to such a listener and, when
 * events are recorded, to the {@link EventLog}, and its end as an event. With neither a listener
 * that wants detail nor a log it builds nothing.
 */
final class StrokeReports {
    private final BallState ball;
    private final Terrain terrain;
    /** The base step: a longer step's path is reported about this often. */
    private final double dt;
    private final double[] sample = new double[3];
    private TrajectoryListener listener;
    /** Whether the listener wants events and the states along long steps ({@link TrajectoryListener#wantsDetail}). */
    private boolean detail;
    /** Null unless the stroke records its events. */
    private EventLog log;

    StrokeReports(BallState ball, Terrain terrain, double dt) {
        this.ball = ball;
        this.terrain = terrain;
        this.dt = dt;
    }

    /** A new stroke: reports go to this listener (may be null), events to a new log if recorded. */
    void start(TrajectoryListener listener, boolean recordEvents) {
        this.listener = listener;
        this.detail = listener != null && listener.wantsDetail();
        this.log = recordEvents ? new EventLog() : null;
    }

    /**
     * The states inside a rolling step longer than dt, from (x0, y0) at v0 and t0 to (x1, y1) at
     * v1 and t1 (its end, reported apart), about every dt, on the cubic through its ends: a
     * listener that traces the path sees it as densely as with steps of dt.
     */
    void path(double x0, double y0, double vx0, double vy0, double t0, double x1, double y1, double vx1, double vy1,
              double t1) {
        if (!detail) return;
        double tau = t1 - t0;
        int pieces = (int) Math.ceil(tau / dt * (1 - 1e-9));
        for (int k = 1; k < pieces; k++) {
            double s = (double) k / pieces;
            double x = PathSweep.hermite(s, x0, vx0 * tau, x1, vx1 * tau);
            double y = PathSweep.hermite(s, y0, vy0 * tau, y1, vy1 * tau);
            double vx = vx0 + s * (vx1 - vx0), vy = vy0 + s * (vy1 - vy0);
            terrain.sample(x, y, sample);
            listener.onState(t0 + s * tau, x, y, sample[0], vx, vy, sample[1] * vx + sample[2] * vy);
        }
    }

    /** The ball's current state, to the listener. */
    void state() {
        TrajectoryListener l = listener;
        if (l == null) return;
        BallState b = ball;
        l.onState(b.t, b.x, b.y, b.z, b.vx, b.vy, b.verticalSpeed());
    }

    /** The ball's current place with a velocity of exactly zero (a ball dropping into the hole). */
    void stateAtRest() {
        if (listener != null) listener.onState(ball.t, ball.x, ball.y, ball.z, 0, 0, 0);
    }

    /** An event where the ball is now; the speeds for impacts, NaN elsewhere. */
    void event(StrokeEvent.Type type, double speedBefore, double speedAfter) {
        if (log == null && !detail) return;
        StrokeEvent e = new StrokeEvent(ball.t, type, ball.x, ball.y, ball.z, speedBefore, speedAfter);
        if (log != null) log.add(e);
        if (detail) listener.onEvent(e);
    }

    /**
     * A ball crushed or caught by a moving obstacle is out of play: it is taken off the course and
     * the stroke ends {@code out} where it began (docs/course-format.md, "Moving obstacles").
     */
    void removedFromPlay() {
        BallState b = ball;
        b.x = b.startX;
        b.y = b.startY;
        b.z = b.startZ;
        finish(Outcome.OUT, b.x, b.y, b.z);
    }

    /** Ends the stroke with this outcome at (ex, ey, ez), and reports it (a timeout is no event). */
    void finish(Outcome result, double ex, double ey, double ez) {
        ball.end(result, ex, ey, ez);
        StrokeEvent.Type type = switch (result) {
            case HOLED -> StrokeEvent.Type.HOLED;
            case STOPPED -> StrokeEvent.Type.STOP;
            case WATER -> StrokeEvent.Type.WATER;
            case OUT -> StrokeEvent.Type.OUT;
            case TIMEOUT -> null;
        };
        if (type != null) event(type, Double.NaN, Double.NaN);
    }

    /** The recorded events; empty unless recorded. */
    List<StrokeEvent> events() {
        return log == null ? List.of() : log.list();
    }
}
