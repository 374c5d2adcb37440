package minigolf.course;

/** The playable rectangle; a ball that leaves it is out of bounds. */
public record Bounds(double minX, double minY, double maxX, double maxY) {
    public boolean contains(double x, double y) {
        return x >= minX && x <= maxX && y >= minY && y <= maxY;
    }

    public double width() {
        return maxX - minX;
    }

    public double depth() {
        return maxY - minY;
    }
}
