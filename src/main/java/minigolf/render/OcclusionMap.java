package minigolf.render;

import minigolf.collision.ObstacleGeometry;
import minigolf.course.Bounds;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;

import java.util.List;

/**
 * Ambient occlusion on the course's ground from what stands on it: the grass darkens towards the
 * foot of a rail, a box or a trunk (a baked contact shadow that the sky's light cannot reach), as
 * a single-channel map over the bounds, 1 open, lower where occluded. Computed on the CPU once per
 * obstacle set (plain Java, testable without GL) and sampled by the terrain shader on the high
 * quality tier. Each obstacle darkens the ground within {@link #REACH} of its footprint by up to
 * {@link #STRENGTH} (times its height's share of {@link #FULL_HEIGHT}), falling off quadratically;
 * several obstacles multiply (a corner is darker than a straight rail).
 */
public final class OcclusionMap {
    /** How far from an obstacle's footprint the ground is darkened (metres). */
    public static final double REACH = 0.14;
    /** The darkening right at the foot of an obstacle at least {@link #FULL_HEIGHT} tall. */
    public static final double STRENGTH = 0.55;
    public static final double FULL_HEIGHT = 0.1;
    /** Texels per metre, at most; the map has at most {@link #MAX_TEXELS} a side. */
    static final double TEXELS_PER_METRE = 50;
    static final int MAX_TEXELS = 512;

    private final Bounds bounds;
    private final int width, height;
    private final float[] values;

    private OcclusionMap(Bounds bounds, int width, int height, float[] values) {
        this.bounds = bounds;
        this.width = width;
        this.height = height;
        this.values = values;
    }

    /** The map over {@code bounds} for these obstacles standing on {@code ground}. */
    public static OcclusionMap of(Bounds bounds, List<Obstacle> obstacles, HeightProbe ground) {
        int w = texels(bounds.width()), h = texels(bounds.depth());
        float[] v = new float[w * h];
        java.util.Arrays.fill(v, 1f);
        OcclusionMap map = new OcclusionMap(bounds, w, h, v);
        for (Obstacle o : obstacles) map.add(o, ground);
        return map;
    }

    private static int texels(double extent) {
        return Math.max(2, Math.min(MAX_TEXELS, (int) Math.ceil(extent * TEXELS_PER_METRE)));
    }

    private void add(Obstacle o, HeightProbe ground) {
        if (o instanceof Obstacle.Wall w) {
            double ax = w.from().x(), ay = w.from().y(), bx = w.to().x(), by = w.to().y();
            double len = Math.hypot(bx - ax, by - ay), half = w.thickness() / 2;
            double ux = len > 0 ? (bx - ax) / len : 1, uy = len > 0 ? (by - ay) / len : 0;
            // The slab: half the thickness either side, reaching half the thickness past its ends.
            stamp(ax - half * ux, ay - half * uy, ux, uy, len + 2 * half, half, w.height());
        } else if (o instanceof Obstacle.Box b) {
            double cx = (b.min().x() + b.max().x()) / 2, cy = (b.min().y() + b.max().y()) / 2;
            double floor = ground.height(cx, cy);
            if (b.min().z() > floor + 0.02) return; // a box in the air does not meet the ground
            double a = Math.toRadians(b.rotationDeg()), ux = Math.cos(a), uy = Math.sin(a);
            double hx = (b.max().x() - b.min().x()) / 2, hy = (b.max().y() - b.min().y()) / 2;
            stamp(cx - hx * ux, cy - hx * uy, ux, uy, 2 * hx, hy, b.max().z() - floor);
        } else if (o instanceof Obstacle.Tree t) {
            double[] c = ObstacleGeometry.treeCylinder(t, ground);
            stamp(c[0], c[1], 1, 0, 0, c[2], t.height());
        }
        // Models (windmills and the like) have no simple footprint: their own shading is left as it is.
    }

    /**
     * Darkens round a footprint: the points within {@code half} of the segment from (sx, sy) along the
     * unit vector (ux, uy) for {@code length} metres (a rounded rectangle; length 0: a disc).
     */
    private void stamp(double sx, double sy, double ux, double uy, double length, double half, double tall) {
        double strength = STRENGTH * Math.min(1, Math.max(0, tall / FULL_HEIGHT));
        if (strength <= 0) return;
        double ex = sx + ux * length, ey = sy + uy * length, reach = half + REACH;
        int i0 = column(Math.min(sx, ex) - reach), i1 = column(Math.max(sx, ex) + reach);
        int j0 = row(Math.min(sy, ey) - reach), j1 = row(Math.max(sy, ey) + reach);
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                double x = bounds.minX() + (i + 0.5) * bounds.width() / width;
                double y = bounds.minY() + (j + 0.5) * bounds.depth() / height;
                double t = Math.max(0, Math.min(length, (x - sx) * ux + (y - sy) * uy));
                double d = Math.max(0, Math.hypot(x - sx - t * ux, y - sy - t * uy) - half);
                if (d >= REACH) continue;
                double f = 1 - d / REACH;
                values[j * width + i] *= (float) (1 - strength * f * f);
            }
        }
    }

    private int column(double x) {
        return Math.max(0, Math.min(width - 1, (int) Math.floor((x - bounds.minX()) / bounds.width() * width)));
    }

    private int row(double y) {
        return Math.max(0, Math.min(height - 1, (int) Math.floor((y - bounds.minY()) / bounds.depth() * height)));
    }

    /** The occlusion factor at (x, y), nearest texel (1 open). */
    public double at(double x, double y) {
        return values[row(y) * width + column(x)];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The map as bytes, row by row from min y (255 open). */
    public byte[] bytes() {
        byte[] out = new byte[values.length];
        for (int k = 0; k < values.length; k++) out[k] = (byte) Math.round(Math.max(0, Math.min(1, values[k])) * 255);
        return out;
    }

    public Bounds bounds() {
        return bounds;
    }
}
