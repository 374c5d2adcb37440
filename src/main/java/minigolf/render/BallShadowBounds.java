package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.HeightProbe;
import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * The screen rectangle that holds the balls' shadows on the ground, so that software rasterisers can
 * shade the balls' analytic shadows (shadow.glsl, BALL_SHADOWS) there only: a second draw of the
 * surfaces within a scissor, instead of a per-ball loop for every pixel of the screen. Plain
 * geometry, no GL.
 *
 * <p>A receiver at p is darkened by a ball of radius r at c when the ray from p towards the sun
 * passes within r + soft(s) of c, soft(s) = 0.15 r + 0.01 s, s the distance along the ray
 * (shadow.glsl). So the shadow lies inside a cylinder round the sun's ray through c: the ground is
 * found along that ray and along 16 rays on the cylinder's (padded) wall, and the rectangle bounds
 * where they start and land: so it also holds a wall or cup the shadow meets on the way down.
 */
final class BallShadowBounds {
    static final int RING_RAYS = 16;
    /** Extra pixels round the projected points (the ground between samples may bulge a little). */
    static final int MARGIN_PX = 4;
    private static final double STEP = 0.05;

    private BallShadowBounds() {
    }

    /**
     * The shadows' screen rectangle {x, y, width, height} (pixels from the bottom left, glScissor's) and
     * the world box round the same rays, min x, y, z, max x, y, z (what stands in it may be shaded).
     */
    record Region(int[] rect, float[] box) {
    }

    /**
     * The region, its rectangle clipped to the viewport; null when no shadow falls on screen. {@code balls} holds centre x, y, z and radius
     * for the first {@code count} balls; {@code toSun} is the unit direction towards the sun;
     * {@code lowest} a height below all of the ground.
     */
    static Region of(float[] balls, int count, Vector3f toSun, HeightProbe ground, Bounds bounds, double lowest,
                    Matrix4f viewProjection, int width, int height) {
        double lx = toSun.x, ly = toSun.y, lz = toSun.z;
        if (lz <= 1e-6) return null; // a sun at or under the horizon casts no shadow on the ground
        // Two unit vectors across the sun's ray.
        Vector3f u = new Vector3f(toSun).cross(Math.abs(toSun.z) < 0.9f ? new Vector3f(0, 0, 1) : new Vector3f(1, 0, 0)).normalize();
        Vector3f w = new Vector3f(toSun).cross(u).normalize();
        ScreenBounds screen = new ScreenBounds(viewProjection, width, height);
        float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int i = 0; i < count; i++) {
            double cx = balls[4 * i], cy = balls[4 * i + 1], cz = balls[4 * i + 2], r = balls[4 * i + 3];
            double centreT = groundAlong(cx, cy, cz, lx, ly, lz, ground, bounds, lowest);
            double s = Double.isNaN(centreT) ? (cz - lowest) / lz : centreT;
            double reach = 1.25 * (1.15 * r + 0.01 * (s + 0.5)) + 0.005;
            for (int k = -1; k < RING_RAYS; k++) {
                double qx = cx, qy = cy, qz = cz;
                if (k >= 0) {
                    double a = 2 * Math.PI * k / RING_RAYS, ca = Math.cos(a) * reach, sa = Math.sin(a) * reach;
                    qx += ca * u.x + sa * w.x;
                    qy += ca * u.y + sa * w.y;
                    qz += ca * u.z + sa * w.z;
                }
                double t = k < 0 ? centreT : groundAlong(qx, qy, qz, lx, ly, lz, ground, bounds, lowest);
                if (Double.isNaN(t)) t = 0; // this ray leaves the course: only what stands on the way
                for (double along : new double[]{0, t}) {
                    float wx = (float) (qx - along * lx), wy = (float) (qy - along * ly), wz = (float) (qz - along * lz);
                    box[0] = Math.min(box[0], wx);
                    box[1] = Math.min(box[1], wy);
                    box[2] = Math.min(box[2], wz);
                    box[3] = Math.max(box[3], wx);
                    box[4] = Math.max(box[4], wy);
                    box[5] = Math.max(box[5], wz);
                    screen.add(wx, wy, wz); // one behind the eye: be safe, shade the whole screen
                }
            }
        }
        int[] rect = screen.rect(MARGIN_PX, MARGIN_PX);
        return rect == null ? null : new Region(rect, box);
    }

    /**
     * The distance t along -toSun from (x, y, z) to the ground, or NaN when the ray leaves the course's
     * bounds first. Marched in 5 cm steps, then bisected to about 0.2 mm.
     */
    static double groundAlong(double x, double y, double z, double lx, double ly, double lz, HeightProbe ground,
                              Bounds bounds, double lowest) {
        double tMax = (z - lowest) / lz;
        double prev = 0;
        if (!inside(x, y, bounds)) return Double.NaN;
        if (z <= ground.height(x, y)) return 0;
        for (double t = STEP; ; t += STEP) {
            double tt = Math.min(t, tMax);
            double px = x - tt * lx, py = y - tt * ly;
            if (!inside(px, py, bounds)) return Double.NaN;
            if (z - tt * lz <= ground.height(px, py)) {
                double lo = prev, hi = tt;
                for (int i = 0; i < 8; i++) {
                    double mid = 0.5 * (lo + hi);
                    if (z - mid * lz <= ground.height(x - mid * lx, y - mid * ly)) hi = mid;
                    else lo = mid;
                }
                return hi;
            }
            if (tt >= tMax) return Double.NaN;
            prev = tt;
        }
    }

    private static boolean inside(double x, double y, Bounds b) {
        return x >= b.minX() && x <= b.maxX() && y >= b.minY() && y <= b.maxY();
    }
}
