package minigolf.physics;

import java.util.List;
import minigolf.course.Magnet;
import minigolf.course.PushZone;
import minigolf.course.Shape;

/**
 * The forces on a rolling ball besides gravity and friction (docs/course-format.md, "Push zones"
 * and "Magnets"): the pushes of the zones that contain the point, added, and the magnets' pulls.
 * Forces are per unit mass (m/s²) in the course plane. Immutable; shared by every stroke.
 *
 * <p>They act as a tilt of the ground would: the rolling equations and the rules for coming to rest
 * see the ground's gradient replaced by the <em>pull gradient</em> P ({@link #pullGradient}),
 * classic P = ∇h − f/g; complete P = ∇h (1 + ∇h·f/g) − D f/g, the horizontal force's part along the
 * tilted ground.
 */
public final class ForceField {
    private final Shape[] pushShapes;
    private final double[] pushX, pushY;
    /** Each push zone's bounding rectangle: minX, minY, maxX, maxY. */
    private final double[] pushBoxes;
    /** Whether each push zone is a rectangle: then its bounding rectangle is the zone (the same comparisons). */
    private final boolean[] pushRect;
    // Magnets: centre, radius, strength (> 0 attracts).
    private final double[] magnetX, magnetY, magnetRadius, magnetStrength;
    // The box round every push zone and magnet, for near().
    private final double minX, minY, maxX, maxY;

    public ForceField(List<PushZone> pushZones, List<Magnet> magnets) {
        int n = pushZones.size();
        pushShapes = new Shape[n];
        pushX = new double[n];
        pushY = new double[n];
        pushBoxes = new double[4 * n];
        pushRect = new boolean[n];
        double x0 = Double.POSITIVE_INFINITY, y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY, y1 = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < n; k++) {
            PushZone z = pushZones.get(k);
            pushShapes[k] = z.shape();
            pushRect[k] = z.shape() instanceof Shape.Rect;
            pushX[k] = z.push().x();
            pushY[k] = z.push().y();
            double[] box = ShapeBoxes.of(z.shape());
            System.arraycopy(box, 0, pushBoxes, 4 * k, 4);
            x0 = Math.min(x0, box[0]);
            y0 = Math.min(y0, box[1]);
            x1 = Math.max(x1, box[2]);
            y1 = Math.max(y1, box[3]);
        }
        int m = magnets.size();
        magnetX = new double[m];
        magnetY = new double[m];
        magnetRadius = new double[m];
        magnetStrength = new double[m];
        for (int k = 0; k < m; k++) {
            Magnet g = magnets.get(k);
            magnetX[k] = g.position().x();
            magnetY[k] = g.position().y();
            magnetRadius[k] = g.radius();
            magnetStrength[k] = g.strength();
            x0 = Math.min(x0, magnetX[k] - magnetRadius[k]);
            y0 = Math.min(y0, magnetY[k] - magnetRadius[k]);
            x1 = Math.max(x1, magnetX[k] + magnetRadius[k]);
            y1 = Math.max(y1, magnetY[k] + magnetRadius[k]);
        }
        minX = x0;
        minY = y0;
        maxX = x1;
        maxY = y1;
    }

    /** Whether there is no push zone and no magnet. */
    public boolean isEmpty() {
        return pushShapes.length == 0 && magnetX.length == 0;
    }

    /** Whether the push jumps somewhere (push zone edges), so that strokes must split steps there. */
    public boolean hasPushZones() {
        return pushShapes.length > 0;
    }

    /** Whether there is a magnet (else the force anywhere is the push there). */
    public boolean hasMagnets() {
        return magnetX.length > 0;
    }

    /** Whether any push zone or magnet reaches into the rectangle. */
    public boolean near(double x0, double y0, double x1, double y1) {
        return x0 <= maxX && x1 >= minX && y0 <= maxY && y1 >= minY;
    }

    /**
     * Whether the force may change within the rectangle: a magnet or a push zone's edge reaches
     * into it. Inside a zone that holds the whole rectangle, or clear of every zone, the push is
     * the same all over it, so a long step may cross it (docs/physics.md, "Step control").
     */
    public boolean mayChangeWithin(double x0, double y0, double x1, double y1) {
        if (!near(x0, y0, x1, y1)) return false;
        for (int k = 0; k < magnetX.length; k++) {
            double r = magnetRadius[k];
            if (magnetX[k] - r <= x1 && magnetX[k] + r >= x0 && magnetY[k] - r <= y1 && magnetY[k] + r >= y0) return true;
        }
        double[] b = pushBoxes;
        for (int k = 0; k < pushShapes.length; k++) {
            if (b[4 * k] > x1 || b[4 * k + 2] < x0 || b[4 * k + 1] > y1 || b[4 * k + 3] < y0) continue;
            if (!ShapeBoxes.covers(pushShapes[k], x0, y0, x1, y1)) return true;
        }
        return false;
    }

    /** The push at (x, y), the sum of the zones containing it, into out[0], out[1]. */
    public void push(double x, double y, double[] out) {
        double px = 0, py = 0;
        if (x < minX || x > maxX || y < minY || y > maxY) {
            out[0] = 0;
            out[1] = 0;
            return;
        }
        for (int k = 0; k < pushShapes.length; k++) {
            if (inZone(k, x, y)) {
                px += pushX[k];
                py += pushY[k];
            }
        }
        out[0] = px;
        out[1] = py;
    }

    /** Whether push zone k holds the point: Shape.Rect's own test, on the stored box, for a rectangle. */
    private boolean inZone(int k, double x, double y) {
        if (!pushRect[k]) return pushShapes[k].contains(x, y);
        double[] b = pushBoxes;
        return x >= b[4 * k] && x <= b[4 * k + 2] && y >= b[4 * k + 1] && y <= b[4 * k + 3];
    }

    /** The magnets' pull at (x, y), added to out[0], out[1]. */
    public void addMagnets(double x, double y, double[] out) {
        for (int k = 0; k < magnetX.length; k++) {
            double dx = x - magnetX[k], dy = y - magnetY[k], r = magnetRadius[k];
            if (Math.abs(dx) >= r || Math.abs(dy) >= r) continue;
            double d = Math.sqrt(dx * dx + dy * dy);
            if (d >= r) continue;
            // f = -s (27/4) (1 - d/R)^2 (p - c) / R: towards the centre for s > 0, |f| = s (27/4) u (1 - u)^2.
            double rest = 1 - d / r;
            double scale = -magnetStrength[k] * 6.75 * rest * rest / r;
            out[0] += scale * dx;
            out[1] += scale * dy;
        }
    }

    /** The whole force (pushes and magnets) at (x, y) into out[0], out[1]. */
    public void force(double x, double y, double[] out) {
        push(x, y, out);
        addMagnets(x, y, out);
    }

    /**
     * The magnets' potential energy per unit mass at (x, y) (J/kg): U with f = -grad U, 0 at each
     * centre, s R 9/16 beyond the rim (the integral of the pull).
     */
    public double magnetPotential(double x, double y) {
        double u = 0;
        for (int k = 0; k < magnetX.length; k++) {
            double r = magnetRadius[k];
            double q = Math.min(1, Math.hypot(x - magnetX[k], y - magnetY[k]) / r);
            u += magnetStrength[k] * r * 6.75 * (q * q * (0.5 - q * (2.0 / 3 - 0.25 * q)));
        }
        return u;
    }

    /**
     * The pull gradient P (docs/course-format.md): the gradient that gravity alone would need to
     * pull as gravity and the force f do together, into out[0], out[1].
     */
    public static void pullGradient(double hx, double hy, double fx, double fy, double gravity, boolean complete,
                                    double[] out) {
        if (complete) {
            double d = 1 + hx * hx + hy * hy;
            double lift = 1 + (hx * fx + hy * fy) / gravity;
            out[0] = hx * lift - d * fx / gravity;
            out[1] = hy * lift - d * fy / gravity;
        } else {
            out[0] = hx - fx / gravity;
            out[1] = hy - fy / gravity;
        }
    }
}
