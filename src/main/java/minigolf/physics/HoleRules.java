package minigolf.physics;

import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.terrain.Terrain;

/**
 * When the ball drops into the hole: at rest within its radius (both rules), passing within it
 * slowly enough under the capture rule, or landing in it from the air slowly enough. The speed
 * limit at a distance delta from the centre is v_c (1 - (delta/r)^2), v_c the hole's capture speed.
 */
final class HoleRules {
    private final BallState ball;
    private final StrokeReports reports;
    private final Terrain terrain;
    private final double holeX;
    private final double holeY;
    private final double holeRadius;
    /** Whether a rolling ball is captured on its way (the capture rule), not only at rest. */
    final boolean captureRule;
    private final double captureSpeed;

    HoleRules(BallState ball, StrokeReports reports, Terrain terrain, Hole hole) {
        this.ball = ball;
        this.reports = reports;
        this.terrain = terrain;
        this.holeX = hole.position().x();
        this.holeY = hole.position().y();
        this.holeRadius = hole.radius();
        this.captureRule = hole.rule() == HoleRule.CAPTURE;
        this.captureSpeed = hole.effectiveCaptureSpeed();
    }

    /** Whether the hole reaches into the rectangle. */
    boolean near(double minX, double minY, double maxX, double maxY) {
        double dx = Math.max(0, Math.max(minX - holeX, holeX - maxX)), dy = Math.max(0, Math.max(minY - holeY, holeY - maxY));
        return dx * dx + dy * dy <= holeRadius * holeRadius;
    }

    /** Whether (qx, qy) is within the hole's radius: a ball at rest there is holed. */
    boolean isInHole(double qx, double qy) {
        double dx = qx - holeX, dy = qy - holeY;
        return dx * dx + dy * dy <= holeRadius * holeRadius;
    }

    /** Whether a flying ball landing at (qx, qy) at this horizontal speed drops in. */
    boolean dropsOnLanding(double qx, double qy, double horizontal) {
        double delta = Math.hypot(qx - holeX, qy - holeY);
        if (delta <= holeRadius) {
            double ratio = delta / holeRadius;
            return horizontal < captureSpeed * (1 - ratio * ratio);
        }
        return false;
    }

    /**
     * The capture rule on the straight segment from the ball to (ex, ey), a rolling step of length
     * tau: the ball drops if it passes within the radius at a speed below the limit, delta its
     * closest approach; then the stroke ends there and this returns true. A segment whose nearest
     * point is its end, while the ball rolls on, leaves the decision to the next segment, where the
     * approach continues.
     */
    boolean captures(double ex, double ey, double speed0, double speed1, double tau, boolean pathEndsHere) {
        double x = ball.x, y = ball.y;
        double dx = ex - x, dy = ey - y;
        double lengthSquared = dx * dx + dy * dy;
        double f = lengthSquared == 0 ? 0
                : Math.max(0, Math.min(1, ((holeX - x) * dx + (holeY - y) * dy) / lengthSquared));
        if (f >= 1 && !pathEndsHere) return false;
        double cx = x + f * dx, cy = y + f * dy;
        double ox = holeX - cx, oy = holeY - cy;
        double delta = Math.sqrt(ox * ox + oy * oy);
        if (delta >= holeRadius) return false;
        double ratio = delta / holeRadius;
        double speedThere = speed0 + f * (speed1 - speed0);
        if (speedThere >= captureSpeed * (1 - ratio * ratio)) return false;
        ball.x = cx;
        ball.y = cy;
        ball.t += f * tau;
        ball.steps++;
        ball.pieceTime = f * tau;
        ball.z = terrain.height(cx, cy);
        ball.vx = 0;
        ball.vy = 0;
        reports.stateAtRest();
        reports.finish(Outcome.HOLED, cx, cy, ball.z);
        return true;
    }
}
