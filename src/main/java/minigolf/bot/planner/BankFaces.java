package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Obstacle;
import minigolf.physics.World;

/** Where the planner's bank shots can bounce: the straight faces of walls and boxes. */
final class BankFaces {
    private BankFaces() {
    }

    /**
     * The straight faces a ball can bank off, each {x0, y0, x1, y1, nx, ny, restitution}: the face
     * moved out by the ball's radius (where the ball's centre is at contact), n pointing away from
     * the obstacle. Walls give their two long sides, boxes their four (not a box raised above a
     * rolling ball, which passes under it).
     */
    static List<double[]> of(World world) {
        double ballRadius = world.physics().ballRadius();
        List<double[]> faces = new ArrayList<>();
        for (Obstacle o : world.course().obstacles()) {
            if (o instanceof Obstacle.Wall w) {
                double dx = w.to().x() - w.from().x(), dy = w.to().y() - w.from().y(), len = Math.hypot(dx, dy);
                if (len < 1e-9) continue;
                double cx = (w.from().x() + w.to().x()) / 2, cy = (w.from().y() + w.to().y()) / 2;
                addRectangleFaces(faces, cx, cy, dx / len, dy / len, len / 2, w.thickness() / 2, ballRadius, w.restitution(), false);
            } else if (o instanceof Obstacle.Box b) {
                double cx = (b.min().x() + b.max().x()) / 2, cy = (b.min().y() + b.max().y()) / 2;
                if (b.min().z() > world.terrain().height(cx, cy) + 2 * ballRadius) continue;
                double a = Math.toRadians(b.rotationDeg());
                addRectangleFaces(faces, (b.min().x() + b.max().x()) / 2, (b.min().y() + b.max().y()) / 2,
                        Math.cos(a), Math.sin(a), (b.max().x() - b.min().x()) / 2, (b.max().y() - b.min().y()) / 2,
                        ballRadius, b.restitution(), true);
            }
        }
        return faces;
    }

    /** A rectangle centred at c with half sizes hu along u and hv across: its long sides (and ends). */
    private static void addRectangleFaces(List<double[]> faces, double cx, double cy, double ux, double uy,
                                          double hu, double hv, double r, double restitution, boolean ends) {
        double vx = -uy, vy = ux;
        for (int s : new int[] {1, -1}) {
            double ox = cx + s * (hv + r) * vx, oy = cy + s * (hv + r) * vy;
            faces.add(new double[] {ox - hu * ux, oy - hu * uy, ox + hu * ux, oy + hu * uy, s * vx, s * vy, restitution});
            if (ends) {
                double ex = cx + s * (hu + r) * ux, ey = cy + s * (hu + r) * uy;
                faces.add(new double[] {ex - hv * vx, ey - hv * vy, ex + hv * vx, ey + hv * vy, s * ux, s * uy, restitution});
            }
        }
    }
}
