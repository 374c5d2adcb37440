package minigolf.physics;

import minigolf.course.Teleport;

/**
 * A stroke's teleports (docs/course-format.md, "Teleports"): finds where a rolling step first
 * enters a teleport's entry, and sends the ball to the exit whose turn it is (or that a seeded
 * teleport draws), with its speed, in its own direction or the exit's. The turns are counted per stroke.
 */
final class Teleporter {
    /** Chords of a step's path checked against the entries (the path strays from them by micrometres). */
    private static final int CHORDS = 8;

    private final TeleportField field;
    private final BallState ball;
    private final RollingTrial trial;
    private final StrokeReports reports;
    /** How many times each teleport has been used in this stroke. */
    private final int[] used;
    /** The teleport the last located entry belongs to. */
    int entered = -1;
    /** The stroke's shot, summarised for the teleports that draw their exits ({@link Teleport#exit}). */
    private long strokeKey;

    Teleporter(TeleportField field, BallState ball, RollingTrial trial, StrokeReports reports) {
        this.field = field;
        this.ball = ball;
        this.trial = trial;
        this.reports = reports;
        this.used = new int[field.size()];
    }

    /** A new stroke, whose shot {@code strokeKey} summarises: every teleport's exits from the first again. */
    void reset(long strokeKey) {
        java.util.Arrays.fill(used, 0);
        entered = -1;
        this.strokeKey = strokeKey;
    }

    /** Whether a teleport's entry reaches into the rectangle of centre positions. */
    boolean near(double minX, double minY, double maxX, double maxY) {
        return field.near(minX, minY, maxX, maxY);
    }

    /** The teleport whose entry the ball is in, or -1. */
    int at() {
        return field.entryAt(ball.x, ball.y);
    }

    /**
     * The first moment within the rolling step [0, tau] (from the ball's state to the trial's end,
     * n*) at which the ball is in an entry, or -1; on return the trial holds the step to that moment
     * and {@link #entered} the teleport. The path is checked as chords of the cubic through both
     * ends; the moment is found by bisection on the integrated step.
     */
    double locate(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        BallState b = ball;
        double x1 = trial.nx, y1 = trial.ny, vx1 = trial.nvx, vy1 = trial.nvy;
        if (!field.near(Math.min(b.x, x1) - 1, Math.min(b.y, y1) - 1, Math.max(b.x, x1) + 1, Math.max(b.y, y1) + 1)) {
            return -1;
        }
        double ax = b.x, ay = b.y;
        for (int k = 1; k <= CHORDS; k++) {
            double s = (double) k / CHORDS;
            double bx = PathSweep.hermite(s, b.x, b.vx * tau, x1, vx1 * tau), by = PathSweep.hermite(s, b.y, b.vy * tau, y1, vy1 * tau);
            double f = field.firstEntry(ax, ay, bx, by);
            if (f <= 1) {
                double before = (k - 1.0) / CHORDS * tau, at = (k - 1.0 + f) / CHORDS * tau;
                double inside = insideNear(before, at, (double) k / CHORDS * tau, kind, a1x, a1y);
                if (inside >= 0) return bisect(before, inside, kind, a1x, a1y);
            }
            ax = bx;
            ay = by;
        }
        trial.run(tau, kind, a1x, a1y);
        return -1;
    }

    /** A moment in [before, end] at which the integrated ball is in an entry (the chord's estimate first), or -1. */
    private double insideNear(double before, double estimate, double end, RollingStep.Kind kind, double a1x, double a1y) {
        trial.run(estimate, kind, a1x, a1y);
        if (field.entryAt(trial.nx, trial.ny) >= 0) return estimate;
        for (int k = 1; k <= 16; k++) {
            double t = before + (end - before) * k / 16;
            trial.run(t, kind, a1x, a1y);
            if (field.entryAt(trial.nx, trial.ny) >= 0) return t;
        }
        return -1;
    }

    /** Bisects between a moment outside every entry and one inside; leaves the trial at the first inside. */
    private double bisect(double outside, double inside, RollingStep.Kind kind, double a1x, double a1y) {
        for (int k = 0; k < StepLocator.LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (outside + inside);
            trial.run(mid, kind, a1x, a1y);
            if (field.entryAt(trial.nx, trial.ny) >= 0) inside = mid; else outside = mid;
        }
        trial.run(inside, kind, a1x, a1y);
        entered = field.entryAt(trial.nx, trial.ny);
        return inside;
    }

    /**
     * Sends the ball in teleport k's entry to the exit whose turn it is: its speed kept, its
     * direction kept or the exit's. Reports the event at the exit.
     */
    void send(int k) {
        BallState b = ball;
        Teleport t = field.get(k);
        Teleport.Exit exit = t.exit(strokeKey, used[k]++);
        double speed = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
        if (exit.directionDeg() != null) {
            double angle = Math.toRadians(exit.directionDeg());
            b.vx = speed * Math.cos(angle);
            b.vy = speed * Math.sin(angle);
        }
        b.x = exit.position().x();
        b.y = exit.position().y();
        b.sampleGround();
        b.z = b.h;
        reports.event(StrokeEvent.Type.TELEPORT, Double.NaN, Double.NaN);
        // An exit inside an entry (the loader refuses it; a course built in code may not) would send
        // the ball round for ever: it is lost, out of play.
        if (field.entryAt(b.x, b.y) >= 0) reports.removedFromPlay();
    }
}
