package minigolf.course;

import java.util.List;

/** A region of the course plane, used by friction zones. */
public sealed interface Shape permits Shape.Rect, Shape.Circle, Shape.Polygon {
    boolean contains(double x, double y);

    record Rect(Vec2 min, Vec2 max) implements Shape {
        public boolean contains(double x, double y) {
            return x >= min.x() && x <= max.x() && y >= min.y() && y <= max.y();
        }
    }

    record Circle(Vec2 center, double radius) implements Shape {
        public boolean contains(double x, double y) {
            double dx = x - center.x(), dy = y - center.y();
            return dx * dx + dy * dy <= radius * radius;
        }
    }

    /** A simple polygon; inside is decided by the even-odd rule. */
    record Polygon(List<Vec2> points) implements Shape {
        public Polygon {
            points = List.copyOf(points);
        }

        public boolean contains(double x, double y) {
            boolean inside = false;
            int n = points.size();
            for (int i = 0, j = n - 1; i < n; j = i++) {
                Vec2 a = points.get(i), b = points.get(j);
                if ((a.y() > y) != (b.y() > y)
                        && x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x()) {
                    inside = !inside;
                }
            }
            return inside;
        }
    }
}
