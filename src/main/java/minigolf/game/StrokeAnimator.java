package minigolf.game;

import minigolf.physics.NonFiniteMotionException;
import minigolf.physics.Stroke;

/**
 * Advances a {@link Stroke} at its fixed physics step, decoupled from the frame rate: each frame
 * adds its real elapsed time and as many whole steps are taken as fit; the ball is drawn between
 * the last two states ({@link #x()}, {@link #y()} interpolate by the time left over). A long
 * frame (a minimised or dragged window) takes at most {@link #MAX_STEPS_PER_FRAME} steps, so the
 * game slows down rather than freezing to catch up.
 */
public final class StrokeAnimator {
    public static final int MAX_STEPS_PER_FRAME = 30;

    private final Stroke stroke;
    private final double dt;
    private double accumulator;
    private double prevX, prevY, prevZ, prevVx, prevVy;
    private double curX, curY, curZ, curVx, curVy;
    /** The course clock at the last two states (moving obstacles are drawn between them, as the ball is). */
    private double prevClock, curClock;
    private double ax, ay;
    private double alpha;

    public StrokeAnimator(Stroke stroke, double dt) {
        this.stroke = stroke;
        this.dt = dt;
        prevX = curX = stroke.x();
        prevY = curY = stroke.y();
        prevZ = curZ = stroke.z();
        prevVx = curVx = stroke.vx();
        prevVy = curVy = stroke.vy();
        prevClock = curClock = stroke.clock();
    }

    /** Advances by {@code seconds} of real time (times {@code speed}, 1 = real time); returns steps taken. */
    public int advance(double seconds, double speed) {
        if (!(seconds > 0) || stroke.isFinished()) return 0;
        accumulator += seconds * speed;
        int taken = 0;
        while (accumulator >= dt && !stroke.isFinished()) {
            if (taken == MAX_STEPS_PER_FRAME) {
                accumulator = 0;
                break;
            }
            prevX = curX;
            prevY = curY;
            prevZ = curZ;
            prevVx = curVx;
            prevVy = curVy;
            prevClock = curClock;
            try {
                stroke.step();
            } catch (NonFiniteMotionException e) {
                // A course whose terrain is not finite somewhere between the loader's samples.
                System.err.println("minigolf: " + e.getMessage() + "; the ball is out of play");
                stroke.endOutOfPlay();
            }
            curX = stroke.isFinished() ? stroke.result().endX() : stroke.x();
            curY = stroke.isFinished() ? stroke.result().endY() : stroke.y();
            // A chip's ball is drawn in the air; an ended stroke (water, the cup) keeps its last height.
            double endZ = stroke.isFinished() ? stroke.result().endZ() : stroke.z();
            curZ = Double.isFinite(endZ) ? endZ : curZ;
            curVx = stroke.vx();
            curVy = stroke.vy();
            curClock = stroke.clock();
            double stepTime = dt;
            ax = (curVx - prevVx) / stepTime;
            ay = (curVy - prevVy) / stepTime;
            accumulator -= dt;
            taken++;
        }
        alpha = stroke.isFinished() ? 1 : Math.min(1, accumulator / dt);
        return taken;
    }

    /** The course clock the frame shows (interpolated as the ball's position is). */
    public double clock() {
        return prevClock + alpha * (curClock - prevClock);
    }

    public boolean isFinished() {
        return stroke.isFinished();
    }

    public Stroke stroke() {
        return stroke;
    }

    /** The drawn position: between the last two states by the fraction of a step left over. */
    public double x() {
        return prevX + (curX - prevX) * alpha;
    }

    public double y() {
        return prevY + (curY - prevY) * alpha;
    }

    /** The drawn height of the ball's contact point: the ground while it rolls, above it in flight. */
    public double z() {
        return prevZ + (curZ - prevZ) * alpha;
    }

    public double vx() {
        return prevVx + (curVx - prevVx) * alpha;
    }

    public double vy() {
        return prevVy + (curVy - prevVy) * alpha;
    }

    /** The mean acceleration over the last step, (v_n - v_(n-1)) / dt. */
    public double ax() {
        return ax;
    }

    public double ay() {
        return ay;
    }
}
