package minigolf.physics;

import java.util.List;

/**
 * What a stroke tells the world: each state to the {@link TrajectoryListener}, each event to the
 * listener and, when events are recorded, to the {@link EventLog}, and its end as an event. With
 * neither a listener nor a log (the bots' hot path) it builds nothing.
 */
final class StrokeReports {
    private final BallState ball;
    private final TrajectoryListener listener;
    /** Null unless the stroke records its events. */
    private final EventLog log;

    StrokeReports(BallState ball, TrajectoryListener listener, boolean recordEvents) {
        this.ball = ball;
        this.listener = listener;
        this.log = recordEvents ? new EventLog() : null;
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
        if (log == null && listener == null) return;
        StrokeEvent e = new StrokeEvent(ball.t, type, ball.x, ball.y, ball.z, speedBefore, speedAfter);
        if (log != null) log.add(e);
        if (listener != null) listener.onEvent(e);
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
