package minigolf.physics;

import java.util.ArrayList;
import java.util.List;

/**
 * A stroke's recorded events. An event that repeats the last one, the same kind within
 * {@link #SAME_PLACE} and {@link #SAME_TIME} of it (a ball rattling in a corner; a ball's lowest
 * bounce takes 29 ms), is merged into it, so the list stays short.
 */
final class EventLog {
    /** Events of one kind this close (m, per axis) to the last recorded one are merged into it... */
    static final double SAME_PLACE = 0.001;
    /** ... when they are also this close in time (s). */
    static final double SAME_TIME = 0.01;

    private final List<StrokeEvent> events = new ArrayList<>();

    void add(StrokeEvent e) {
        if (!repeatsLast(e)) events.add(e);
    }

    List<StrokeEvent> list() {
        return events;
    }

    private boolean repeatsLast(StrokeEvent e) {
        if (events.isEmpty()) return false;
        StrokeEvent last = events.get(events.size() - 1);
        return last.type() == e.type() && e.t() - last.t() <= SAME_TIME && Math.abs(last.x() - e.x()) <= SAME_PLACE
                && Math.abs(last.y() - e.y()) <= SAME_PLACE && Math.abs(last.z() - e.z()) <= SAME_PLACE;
    }
}
