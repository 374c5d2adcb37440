package minigolf.collision;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The outline hulls that let anyShapeNearPath test a run of triangles at once. */
class PathProximityTest {
    @Test
    void aBoxsTwelveTrianglesSeenFromAboveAreItsFootprint() {
        // The corners of a 2 x 1 box's faces, seen from above: each corner many times over, and
        // the side faces' triangles lying on the footprint's edges.
        double[][] corners = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
        double[] points = new double[2 * 36];
        for (int k = 0; k < 36; k++) {
            double[] c = corners[(k * 7) % 4];
            points[2 * k] = c[0];
            points[2 * k + 1] = c[1];
        }
        double[] hull = new double[2 * 36];
        int n = PathProximity.convexHull(points, 36, hull, 0);
        assertEquals(4, n);
        // Counter-clockwise from the lowest-left corner.
        assertArrayEquals(new double[] {0, 0, 2, 0, 2, 1, 0, 1}, Arrays.copyOf(hull, 8));
    }

    @Test
    void pointsOnALineMakeASegmentAndOnePointItself() {
        double[] line = {0, 0, 3, 3, 1, 1, 2, 2, 3, 3};
        double[] out = new double[10];
        assertEquals(2, PathProximity.convexHull(line, 5, out, 0));
        assertArrayEquals(new double[] {0, 0, 3, 3}, Arrays.copyOf(out, 4));
        double[] one = {0.5, -2, 0.5, -2};
        assertEquals(1, PathProximity.convexHull(one, 2, out, 2));
        assertArrayEquals(new double[] {0.5, -2}, Arrays.copyOfRange(out, 2, 4));
    }

    @Test
    void everyPointLiesInsideItsHullAndEveryHullPointIsOneOfThem() {
        Random random = new Random(3);
        for (int trial = 0; trial < 2_000; trial++) {
            int n = 1 + random.nextInt(48);
            double[] p = new double[2 * n];
            for (int i = 0; i < 2 * n; i++) p[i] = Math.round(random.nextGaussian() * 8) / 4.0; // repeats and lines
            double[] hull = new double[2 * n + 2];
            int h = PathProximity.convexHull(p, n, hull, 0);
            assertTrue(h >= 1 && h <= n);
            for (int k = 0; k < h; k++) {
                boolean found = false;
                for (int i = 0; i < n && !found; i++) found = p[2 * i] == hull[2 * k] && p[2 * i + 1] == hull[2 * k + 1];
                assertTrue(found, "hull point " + k + " is one of the points");
            }
            for (int k = 0; k < h && h > 2; k++) {
                int next = (k + 1) % h;
                double ex = hull[2 * next] - hull[2 * k], ey = hull[2 * next + 1] - hull[2 * k + 1];
                for (int i = 0; i < n; i++) {
                    double cross = ex * (p[2 * i + 1] - hull[2 * k + 1]) - ey * (p[2 * i] - hull[2 * k]);
                    assertTrue(cross >= 0, "point " + i + " left of (or on) edge " + k + " of trial " + trial);
                }
            }
        }
    }

    /**
     * The points inside the extreme points' quadrilateral are dropped before the sort: the hull is
     * the same, point for point, as the monotone chain over all of them (a reference written here,
     * with a boxed sort), on grids with repeats, lines and the 36 corners of a box's faces.
     */
    @Test
    void droppingInnerPointsKeepsTheHullPointForPoint() {
        Random random = new Random(21);
        for (int trial = 0; trial < 5_000; trial++) {
            int n = 1 + random.nextInt(48);
            double scale = trial % 3 == 0 ? 4.0 : 1024.0;
            double[] p = new double[2 * n];
            for (int i = 0; i < 2 * n; i++) p[i] = Math.round(random.nextGaussian() * scale) / scale;
            if (trial % 7 == 0) {
                for (int i = 0; i < n; i++) p[2 * i + 1] = 0.5 * p[2 * i] + 1; // all on one line
            }
            double[] hull = new double[2 * n + 2], reference = new double[2 * n + 2];
            int h = PathProximity.convexHull(p, n, hull, 0);
            int r = referenceHull(p, n, reference);
            assertEquals(r, h, "trial " + trial);
            assertArrayEquals(Arrays.copyOf(reference, 2 * r), Arrays.copyOf(hull, 2 * h), "trial " + trial);
        }
    }

    /** Andrew's monotone chain over every point, counter-clockwise from the lowest-left, no collinear points. */
    private static int referenceHull(double[] p, int n, double[] out) {
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> p[2 * a] != p[2 * b] ? Double.compare(p[2 * a], p[2 * b])
                : Double.compare(p[2 * a + 1], p[2 * b + 1]));
        int[] chain = new int[2 * n + 1];
        int h = 0;
        for (int r = 0; r < n; r++) {
            while (h >= 2 && turn(p, chain[h - 2], chain[h - 1], order[r]) <= 0) h--;
            chain[h++] = order[r];
        }
        for (int r = n - 2, lower = h + 1; r >= 0; r--) {
            while (h >= lower && turn(p, chain[h - 2], chain[h - 1], order[r]) <= 0) h--;
            chain[h++] = order[r];
        }
        h--;
        if (h < 1 || (h == 2 && p[2 * chain[0]] == p[2 * chain[1]] && p[2 * chain[0] + 1] == p[2 * chain[1] + 1])) h = 1;
        for (int k = 0; k < h; k++) {
            out[2 * k] = p[2 * chain[k]];
            out[2 * k + 1] = p[2 * chain[k] + 1];
        }
        return h;
    }

    private static double turn(double[] p, int a, int b, int c) {
        return (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
    }
}
