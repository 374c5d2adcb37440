package minigolf.physics;

import minigolf.course.Shape;
import minigolf.course.Vec2;

/** The bounding rectangle of a course shape, {minX, minY, maxX, maxY}. */
public final class ShapeBoxes {
    private ShapeBoxes() {
    }

    /** The rectangle round the shape (for cells, round the cells that are set; an empty grid gives its origin). */
    public static double[] of(Shape shape) {
        if (shape instanceof Shape.Rect r) return new double[] {r.min().x(), r.min().y(), r.max().x(), r.max().y()};
        if (shape instanceof Shape.Circle c) {
            double x = c.center().x(), y = c.center().y(), r = c.radius();
            return new double[] {x - r, y - r, x + r, y + r};
        }
        if (shape instanceof Shape.Cells c) return cellsBox(c);
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (Vec2 p : ((Shape.Polygon) shape).points()) {
            box[0] = Math.min(box[0], p.x());
            box[1] = Math.min(box[1], p.y());
            box[2] = Math.max(box[2], p.x());
            box[3] = Math.max(box[3], p.y());
        }
        return box;
    }

    /**
     * Whether the shape certainly holds the whole rectangle (a rectangle or a circle holding its
     * four corners: both are convex); false where it may not, as for polygons.
     */
    static boolean covers(Shape shape, double minX, double minY, double maxX, double maxY) {
        return (shape instanceof Shape.Rect || shape instanceof Shape.Circle)
                && shape.contains(minX, minY) && shape.contains(maxX, minY)
                && shape.contains(minX, maxY) && shape.contains(maxX, maxY);
    }

    private static double[] cellsBox(Shape.Cells c) {
        int[] spans = c.spans();
        if (spans.length == 0) return new double[] {c.origin().x(), c.origin().y(), c.origin().x(), c.origin().y()};
        int r0 = Integer.MAX_VALUE, r1 = Integer.MIN_VALUE, c0 = Integer.MAX_VALUE, c1 = Integer.MIN_VALUE;
        for (int i = 0; i < spans.length; i += 3) {
            r0 = Math.min(r0, spans[i]);
            r1 = Math.max(r1, spans[i]);
            c0 = Math.min(c0, spans[i + 1]);
            c1 = Math.max(c1, spans[i + 2]);
        }
        double s = c.size(), x = c.origin().x(), y = c.origin().y();
        return new double[] {x + c0 * s, y + r0 * s, x + c1 * s, y + (r1 + 1) * s};
    }
}
