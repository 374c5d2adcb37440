package minigolf.bot.planner;

import minigolf.bot.Shot;

/** Where the ball's path passes nearest the hole, and its velocity there (steps interpolated). */
final class Approach implements minigolf.physics.TrajectoryListener {
    final double hx, hy;
    double lastX, lastY, lastVx, lastVy;
    double best, cx, cy, cvx, cvy, dirX, dirY;
    boolean collided;

    Approach(double hx, double hy, double x0, double y0, Shot shot) {
        this.hx = hx;
        this.hy = hy;
        lastX = x0;
        lastY = y0;
        lastVx = shot.vx();
        lastVy = shot.vy();
        cx = x0;
        cy = y0;
        cvx = lastVx;
        cvy = lastVy;
        best = (x0 - hx) * (x0 - hx) + (y0 - hy) * (y0 - hy);
        double s = Math.max(Math.hypot(lastVx, lastVy), 1e-12);
        dirX = lastVx / s;
        dirY = lastVy / s;
    }

    @Override
    public void onStep(double t, double x, double y, double vx, double vy) {
        double dx = x - lastX, dy = y - lastY;
        double len2 = dx * dx + dy * dy;
        double f = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((hx - lastX) * dx + (hy - lastY) * dy) / len2));
        double qx = lastX + f * dx, qy = lastY + f * dy;
        double d = (qx - hx) * (qx - hx) + (qy - hy) * (qy - hy);
        if (d < best) {
            best = d;
            cx = qx;
            cy = qy;
            cvx = lastVx + f * (vx - lastVx);
            cvy = lastVy + f * (vy - lastVy);
            if (len2 > 0) {
                double l = Math.sqrt(len2);
                dirX = dx / l;
                dirY = dy / l;
            }
        }
        lastX = x;
        lastY = y;
        lastVx = vx;
        lastVy = vy;
    }

    @Override
    public void onEvent(minigolf.physics.StrokeEvent event) {
        if (event.type() == minigolf.physics.StrokeEvent.Type.COLLISION) collided = true;
    }
}
