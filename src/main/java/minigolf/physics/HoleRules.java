package minigolf.physics;

import java.util.List;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.terrain.Terrain;

/**
 * When the ball drops into a hole: at rest within its radius (both rules), passing within it
 * slowly enough under the capture rule, or landing in it from the air slowly enough. The speed
 * limit at a distance delta from the centre is v_c (1 - (delta/r)^2), v_c the hole's capture speed.
 * A course may have several holes (the classic tracks): any of them ends the stroke, the first the
 * ball reaches along its path.
 */
final class HoleRules {
    private final BallState ball;
    private final StrokeReports reports;
    private final Terrain terrain;
    private final double[] holeX;
    private final double[] holeY;
    private final double[] holeRadius;
    private final double[] captureSpeed;
    private final boolean[] captures;
    /** Whether a rolling ball is captured on its way (the capture rule of any hole), not only at rest. */
    final boolean captureRule;

    HoleRules(BallState ball, StrokeReports reports, Terrain terrain, List<Hole> holes) {
        this.ball = ball;
        this.reports = reports;
        this.terrain = terrain;
        int n = holes.size();
        holeX = new double[n];
        holeY = new double[n];
        holeRadius = new double[n];
        captureSpeed = new double[n];
        captures = new boolean[n];
        boolean any = false;
        for (int i = 0; i < n; i++) {
            Hole h = holes.get(i);
            holeX[i] = h.position().x();
            holeY[i] = h.position().y();
            holeRadius[i] = h.radius();
            captureSpeed[i] = h.effectiveCaptureSpeed();
            captures[i] = h.rule() == HoleRule.CAPTURE;
            any |= captures[i];
        }
        captureRule = any;
    }

    /** Whether a hole under the capture rule reaches into the rectangle. */
    boolean near(double minX, double minY, double maxX, double maxY) {
        for (int i = 0; i < holeX.length; i++) {
            if (!captures[i]) continue;
            double dx = Math.max(0, Math.max(minX - holeX[i], holeX[i] - maxX));
            double dy = Math.max(0, Math.max(minY - holeY[i], holeY[i] - maxY));
            if (dx * dx + dy * dy <= holeRadius[i] * holeRadius[i]) return true;
        }
        return false;
    }

    /** Whether (qx, qy) is within a hole's radius: a ball at rest there is holed. */
    boolean isInHole(double qx, double qy) {
        for (int i = 0; i < holeX.length; i++) {
            double dx = qx - holeX[i], dy = qy - holeY[i];
            if (dx * dx + dy * dy <= holeRadius[i] * holeRadius[i]) return true;
        }
        return false;
    }

    /** Whether a flying ball landing at (qx, qy) at this horizontal speed drops in. */
    boolean dropsOnLanding(double qx, double qy, double horizontal) {
        for (int i = 0; i < holeX.length; i++) {
            double delta = Math.hypot(qx - holeX[i], qy - holeY[i]);
            if (delta <= holeRadius[i]) {
                double ratio = delta / holeRadius[i];
                if (horizontal < captureSpeed[i] * (1 - ratio * ratio)) return true;
            }
        }
        return false;
    }

    /**
     * The capture rule on the straight segment from the ball to (ex, ey), a rolling step of length
     * tau: the ball drops if it passes within a hole's radius at a speed below the limit, delta its
     * closest approach; then the stroke ends there and this returns true. A segment whose nearest
     * point is its end, while the ball rolls on, leaves the decision to the next segment, where the
     * approach continues. Of several holes that would capture, the one passed first wins.
     */
    boolean captures(double ex, double ey, double speed0, double speed1, double tau, boolean pathEndsHere) {
        double x = ball.x, y = ball.y;
        double dx = ex - x, dy = ey - y;
        double lengthSquared = dx * dx + dy * dy;
        double first = Double.POSITIVE_INFINITY;
        for (int i = 0; i < holeX.length; i++) {
            if (!captures[i]) continue;
            double f = lengthSquared == 0 ? 0
                    : Math.max(0, Math.min(1, ((holeX[i] - x) * dx + (holeY[i] - y) * dy) / lengthSquared));
            if (f >= first || (f >= 1 && !pathEndsHere)) continue;
            double ox = holeX[i] - (x + f * dx), oy = holeY[i] - (y + f * dy);
            double delta = Math.sqrt(ox * ox + oy * oy);
            if (delta >= holeRadius[i]) continue;
            double ratio = delta / holeRadius[i];
            double speedThere = speed0 + f * (speed1 - speed0);
            if (speedThere < captureSpeed[i] * (1 - ratio * ratio)) first = f;
        }
        if (first == Double.POSITIVE_INFINITY) return false;
        double cx = x + first * dx, cy = y + first * dy;
        ball.x = cx;
        ball.y = cy;
        ball.t += first * tau;
        ball.steps++;
        ball.pieceTime = first * tau;
        ball.z = terrain.height(cx, cy);
        ball.vx = 0;
        ball.vy = 0;
        reports.stateAtRest();
        reports.finish(Outcome.HOLED, cx, cy, ball.z);
        return true;
    }
}
