package minigolf.physics;

import java.util.List;
import minigolf.course.Shape;
import minigolf.course.Teleport;

/**
 * The course's teleports for the engine (docs/course-format.md, "Teleports"): which entry holds a
 * point and where a path first enters one. Immutable; which exit comes next is a stroke's own
 * ({@link RollingPhase}).
 */
public final class TeleportField {
    private final Teleport[] teleports;
    private final double[] boxes;

    TeleportField(List<Teleport> teleports) {
        this.teleports = teleports.toArray(new Teleport[0]);
        boxes = new double[4 * this.teleports.length];
        for (int k = 0; k < this.teleports.length; k++) {
            System.arraycopy(ShapeBoxes.of(this.teleports[k].entry()), 0, boxes, 4 * k, 4);
        }
    }

    public int size() {
        return teleports.length;
    }

    public Teleport get(int k) {
        return teleports[k];
    }

    /** The teleport whose entry holds (x, y) (the first in the course's order), or -1. */
    public int entryAt(double x, double y) {
        for (int k = 0; k < teleports.length; k++) {
            if (x >= boxes[4 * k] && x <= boxes[4 * k + 2] && y >= boxes[4 * k + 1] && y <= boxes[4 * k + 3]
                    && teleports[k].entry().contains(x, y)) {
                return k;
            }
        }
        return -1;
    }

    /** Whether an entry reaches into the rectangle. */
    public boolean near(double minX, double minY, double maxX, double maxY) {
        for (int k = 0; k < teleports.length; k++) {
            if (boxes[4 * k] <= maxX && boxes[4 * k + 2] >= minX && boxes[4 * k + 1] <= maxY && boxes[4 * k + 3] >= minY) {
                return true;
            }
        }
        return false;
    }

    /** The first fraction of the segment a-b inside any entry, or +infinity. */
    double firstEntry(double ax, double ay, double bx, double by) {
        double minX = Math.min(ax, bx), maxX = Math.max(ax, bx), minY = Math.min(ay, by), maxY = Math.max(ay, by);
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < teleports.length; k++) {
            if (boxes[4 * k] > maxX || boxes[4 * k + 2] < minX || boxes[4 * k + 1] > maxY || boxes[4 * k + 3] < minY) continue;
            Shape entry = teleports[k].entry();
            best = Math.min(best, ShapeCrossing.firstEntry(entry, ax, ay, bx, by));
        }
        return best;
    }
}
