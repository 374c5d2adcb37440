package minigolf.render;

/**
 * The ball dropping into the cup: from where the physics says it was captured it slides to the
 * cup's centre and sinks out of sight below the green (the terrain hides it) within
 * {@link #DURATION} seconds, falling faster as it goes. Plain Java; the game asks it for the ball
 * to draw each frame ({@link #view()}), the renderer draws that like any other ball.
 */
public final class CupDrop {
    /** Seconds from capture to out of sight. */
    public static final double DURATION = 0.35;
    /** How deep the ball's lowest point sinks, in ball radii (it is out of sight well before). */
    static final double DEPTH_RADII = 2.5;

    private double x0, y0, hx, hy, ground, radius;
    private float red, green, blue;
    private double started = Double.NaN, now = Double.NaN;
    private boolean active;

    /** Starts a drop from (x, y) into the cup at (hx, hy) on ground height {@code ground}, at the next frame's time. */
    public void start(double x, double y, double hx, double hy, double ground, double radius, float[] rgb) {
        this.x0 = x;
        this.y0 = y;
        this.hx = hx;
        this.hy = hy;
        this.ground = ground;
        this.radius = radius;
        this.red = rgb[0];
        this.green = rgb[1];
        this.blue = rgb[2];
        this.started = Double.NaN;
        this.active = true;
    }

    /** Advances to the frame's time (seconds); the first call after {@link #start} is the drop's start. */
    public void advanceTo(double time) {
        if (!active) return;
        if (Double.isNaN(started)) started = time;
        now = time;
        if (now - started >= DURATION) active = false;
    }

    public boolean isActive() {
        return active;
    }

    /** The ball to draw now, or null when no drop is under way. */
    public BallView view() {
        if (!active) return null;
        double s = Double.isNaN(started) ? 0 : Math.min(1, (now - started) / DURATION);
        double slide = Math.min(1, 2 * s); // to the centre in the first half
        double x = x0 + (hx - x0) * slide, y = y0 + (hy - y0) * slide;
        double z = ground - DEPTH_RADII * radius * s * s; // it falls, faster and faster
        return new BallView((float) x, (float) y, (float) z, red, green, blue);
    }

    /** Stops a drop (a new hole, a replay). */
    public void clear() {
        active = false;
    }
}
