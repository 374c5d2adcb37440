package minigolf.course;

import java.util.Arrays;
import java.util.List;

/** A region of the course plane, used by friction zones. */
public sealed interface Shape permits Shape.Rect, Shape.Circle, Shape.Polygon, Shape.Cells {
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

    /**
     * Square cells of a grid: the cells listed in {@code spans}, each span {row, first column,
     * column after the last} (row 0 the cells from origin.y to origin.y + size). Made for areas drawn
     * pixel by pixel, as the classic tracks' surfaces: inside is a constant-time lookup whatever
     * the outline. A cell includes its lower-left edges, not its upper-right ones.
     */
    final class Cells implements Shape {
        private final Vec2 origin;
        private final double size;
        private final int columns;
        private final int rows;
        private final int[] spans;
        private final long[] bits;

        /**
         * @param spans triples {row, start, end}, in any order, possibly overlapping: stored sorted and merged
         * @throws IllegalArgumentException a span outside the grid or empty, a size not positive
         */
        public Cells(Vec2 origin, double size, int columns, int rows, int[] spans) {
            if (!(size > 0) || columns < 1 || rows < 1) throw new IllegalArgumentException("a grid needs size > 0 and cells");
            if (spans.length % 3 != 0) throw new IllegalArgumentException("spans are triples");
            this.origin = origin;
            this.size = size;
            this.columns = columns;
            this.rows = rows;
            this.bits = new long[(int) (((long) columns * rows + 63) / 64)];
            for (int i = 0; i < spans.length; i += 3) {
                int r = spans[i], a = spans[i + 1], b = spans[i + 2];
                if (r < 0 || r >= rows || a < 0 || b > columns || a >= b) {
                    throw new IllegalArgumentException("span [" + r + ", " + a + ", " + b + "] is outside the "
                            + columns + " x " + rows + " grid or empty");
                }
                for (int c = a; c < b; c++) {
                    long k = (long) r * columns + c;
                    bits[(int) (k >>> 6)] |= 1L << (k & 63);
                }
            }
            this.spans = canonicalSpans();
        }

        private int[] canonicalSpans() {
            int[] out = new int[48];
            int n = 0;
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < columns; ) {
                    if (!cell(c, r)) {
                        c++;
                        continue;
                    }
                    int start = c;
                    while (c < columns && cell(c, r)) c++;
                    if (n + 3 > out.length) out = Arrays.copyOf(out, out.length * 2);
                    out[n++] = r;
                    out[n++] = start;
                    out[n++] = c;
                }
            }
            return Arrays.copyOf(out, n);
        }

        /** Whether cell (column, row) is in the shape. */
        public boolean cell(int column, int row) {
            if (column < 0 || row < 0 || column >= columns || row >= rows) return false;
            long k = (long) row * columns + column;
            return (bits[(int) (k >>> 6)] >>> (k & 63) & 1) != 0;
        }

        public boolean contains(double x, double y) {
            double u = (x - origin.x()) / size, v = (y - origin.y()) / size;
            if (!(u >= 0 && v >= 0 && u < columns && v < rows)) return false;
            return cell((int) u, (int) v);
        }

        public Vec2 origin() {
            return origin;
        }

        public double size() {
            return size;
        }

        public int columns() {
            return columns;
        }

        public int rows() {
            return rows;
        }

        /** The cells as sorted, merged triples {row, start, end} (a copy). */
        public int[] spans() {
            return spans.clone();
        }

        public int spanCount() {
            return spans.length / 3;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Cells c && origin.equals(c.origin) && Double.compare(size, c.size) == 0
                    && columns == c.columns && rows == c.rows && Arrays.equals(spans, c.spans);
        }

        @Override
        public int hashCode() {
            return origin.hashCode() * 31 + Arrays.hashCode(spans);
        }

        @Override
        public String toString() {
            return "Cells[" + columns + " x " + rows + " of " + size + " at " + origin + ", " + spanCount() + " spans]";
        }
    }
}
