package minigolf.render;

import minigolf.course.Segments;

/**
 * Which of the sky's ground cells can show the seaside's shore (beach, foam, the water's edge) and
 * so need sky.frag's per-pixel sea (SEA_PIXEL); the others are wholly grass or wholly open sea, whose
 * colour the sky's grid corners already give (sky.vert), so a software rasteriser can skip the
 * per-pixel work there. A cell below the horizon is a convex quadrilateral on the ground plane; the
 * distance from the course's rectangle is convex, so the quad's largest distance is at a corner and
 * its smallest is the distance between the two convex shapes. Plain geometry, no GL.
 */
final class ShoreCells {
    private ShoreCells() {
    }

    /**
     * Whether the ground quad with corners (xs[i], ys[i]), i = 0..3 in order round it, lies wholly
     * nearer to the rectangle {minX, minY, maxX, maxY} than {@code inner} or wholly further than
     * {@code outer}: then nothing of the shore's band between the two shows in it.
     */
    static boolean outsideBand(float[] xs, float[] ys, float[] rect, float inner, float outer) {
        float far = 0;
        for (int i = 0; i < 4; i++) far = Math.max(far, distanceToRect(xs[i], ys[i], rect));
        if (far < inner) return true;
        return distanceQuadToRect(xs, ys, rect) > outer;
    }

    static float distanceToRect(float x, float y, float[] r) {
        float dx = Math.max(Math.max(r[0] - x, x - r[2]), 0), dy = Math.max(Math.max(r[1] - y, y - r[3]), 0);
        return (float) Math.hypot(dx, dy);
    }

    /** The distance between a convex quad and an axis-aligned rectangle (0 where they overlap). */
    static float distanceQuadToRect(float[] xs, float[] ys, float[] r) {
        float[] rx = {r[0], r[2], r[2], r[0]}, ry = {r[1], r[1], r[3], r[3]};
        for (int i = 0; i < 4; i++) {
            if (distanceToRect(xs[i], ys[i], r) == 0) return 0;
            if (insideQuad(xs, ys, rx[i], ry[i])) return 0;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < 4; i++) {
            int j = (i + 1) % 4;
            for (int k = 0; k < 4; k++) {
                int l = (k + 1) % 4;
                best = Math.min(best, segmentDistance(xs[i], ys[i], xs[j], ys[j], rx[k], ry[k], rx[l], ry[l]));
            }
        }
        return (float) best;
    }

    /** Whether (x, y) lies inside the convex quad (either winding). */
    static boolean insideQuad(float[] xs, float[] ys, float x, float y) {
        int positive = 0, negative = 0;
        for (int i = 0; i < 4; i++) {
            int j = (i + 1) % 4;
            double cross = (xs[j] - xs[i]) * (double) (y - ys[i]) - (ys[j] - ys[i]) * (double) (x - xs[i]);
            if (cross > 0) positive++;
            if (cross < 0) negative++;
        }
        return positive == 0 || negative == 0;
    }

    static double segmentDistance(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        if (segmentsCross(ax, ay, bx, by, cx, cy, dx, dy)) return 0;
        return Math.min(Math.min(Segments.distance(ax, ay, cx, cy, dx, dy), Segments.distance(bx, by, cx, cy, dx, dy)),
                Math.min(Segments.distance(cx, cy, ax, ay, bx, by), Segments.distance(dx, dy, ax, ay, bx, by)));
    }

    private static boolean segmentsCross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double d1 = Segments.side(cx, cy, dx, dy, ax, ay), d2 = Segments.side(cx, cy, dx, dy, bx, by);
        double d3 = Segments.side(ax, ay, bx, by, cx, cy), d4 = Segments.side(ax, ay, bx, by, dx, dy);
        return d1 * d2 < 0 && d3 * d4 < 0;
    }
}
