package minigolf.physics.reference;

import minigolf.physics.Outcome;

/**
 * The end of one reference stroke. {@code covered} is false when the shot ran past the
 * reference's guards (more than 1,000 obstacle contacts: a ball wedged between obstacles; or
 * more than a million steps);
 * {@code note} then says which, and the other fields are where the reference gave up.
 * {@code launches} counts the times the ball left the ground, {@code contacts} its obstacle hits.
 */
public record ReferenceResult(Outcome outcome, double endX, double endY, double time, boolean covered,
                              String note, long steps, int launches, int contacts) {
    ReferenceResult(Outcome outcome, double endX, double endY, double time, boolean covered, String note, long steps) {
        this(outcome, endX, endY, time, covered, note, steps, 0, 0);
    }

    static ReferenceResult notCovered(String why, double x, double y, double t, long steps) {
        return new ReferenceResult(null, x, y, t, false, why, steps);
    }

    ReferenceResult withCounts(int newLaunches, int newContacts) {
        return new ReferenceResult(outcome, endX, endY, time, covered, note, steps, newLaunches, newContacts);
    }
}
