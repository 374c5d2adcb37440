package minigolf.physics;

import minigolf.course.Zone;

/**
 * Where the ball lies after a stroke and how many penalty strokes it cost, by the course's rules:
 * water and out of bounds put the ball back where the stroke began with one penalty stroke; a
 * hazard zone (docs/course-format.md) says itself where the ball goes (the stroke's start or the
 * course's start) and whether a penalty stroke is added. The game and the bots' play-throughs
 * both apply it, so they count alike.
 *
 * @param back whether the ball was put back (it did not stay where the stroke ended)
 */
public record Landing(double x, double y, int penalty, boolean back) {
    /** The landing of stroke result {@code r} played from (startX, startY). */
    public static Landing of(World world, ShotResult r, double startX, double startY) {
        if (!r.outcome().isPenalty()) return new Landing(r.endX(), r.endY(), 0, false);
        Zone.Hazard h = r.outcome() == Outcome.WATER ? world.friction().hazardAt(r.endX(), r.endY()) : null;
        if (h == null) return new Landing(startX, startY, 1, true);
        if (h.returnTo() == Zone.Hazard.ReturnTo.COURSE_START) {
            return new Landing(world.course().start().x(), world.course().start().y(), h.penalty(), true);
        }
        return new Landing(startX, startY, h.penalty(), true);
    }
}
