package minigolf.physics.reference;

import minigolf.physics.Outcome;

/**
 * The end of one reference stroke. {@code covered} is false when the shot needs physics the
 * reference does not model (flight, a ball left resting against an obstacle) or ran past its step
 * guard; {@code note} then says which, and the other fields are where the reference gave up.
 */
public record ReferenceResult(Outcome outcome, double endX, double endY, double time, boolean covered,
                              String note, long steps) {
    static ReferenceResult notCovered(String why, double x, double y, double t, long steps) {
        return new ReferenceResult(null, x, y, t, false, why, steps);
    }
}
