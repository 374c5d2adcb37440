package minigolf.physics;

import minigolf.course.Shape;
import minigolf.course.Vec2;

/** The bounding rectangle of a course shape, {minX, minY, maxX, maxY}. */
final class ShapeBoxes {
    private ShapeBoxes() {
    }

    static double[] of(Shape shape) {
        if (shape instanceof Shape.Rect r) return new double[] {r.min().x(), r.min().y(), r.max().x(), r.max().y()};
        if (shape instanceof Shape.Circle c) {
            double x = c.center().x(), y = c.center().y(), r = c.radius();
            return new double[] {x - r, y - r, x + r, y + r};
        }
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
}
