package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Shot;
import minigolf.bot.search.SpeedGuess;

/**
 * The planner's first stage: a hole-in-one. Broyden straight at the hole, bank lines off walls and
 * boxes, a sweep of directions round the shortest path and the hole's direction (promising rest
 * points start Broyden again), and among obstacles a fine sweep round the promising shots.
 */
final class HoleInOne {
    /** The sweep gives up when its first this many shots (about ±48° round both directions) are all lost. */
    static final int SWEEP_ALL_LOST = 24;
    /** The fine sweep's step near shots that hit obstacles, and how many shots it may spend per stroke. */
    static final double FINE_STEP = Math.toRadians(0.1);
    static final int FINE_PROBES = 400;
    /** Bank lines (shortest first) Broyden starts from. */
    static final int BANK_TRIES = 4;
    static final double BANK_FAN_STEP = Math.toRadians(1);
    static final int BANK_FAN = 8;

    private final Stroke s;

    HoleInOne(Stroke s) {
        this.s = s;
    }

    Shot holeInOne() {
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        Shot direct = s.guess(holeAngle, Math.hypot(s.holeX - s.px, s.holeY - s.py));
        Attempt first = s.solveHole(direct, null);
        if (first.holed()) return first.shot();
        // Reuse: when the straight shot was lost (water on the line), the sweep's faster shot
        // along the same line is lost too; it is not probed again.
        boolean lineLost = s.firstEval != null && s.firstEval.penalty()
                && Math.abs(Math.atan2(s.firstEval.shot().vy(), s.firstEval.shot().vx()) - holeAngle) < 1e-9;
        s.sim.phase("bank");
        Shot bank = bankShot();
        if (bank != null) return bank;
        s.sim.phase("sweep");
        List<Candidate> candidates = new ArrayList<>();
        List<double[]> promising = new ArrayList<>();
        boolean obstacles = false;
        boolean reachTested = false;
        boolean pathShot = true;
        int lost = 0;
        for (double angle : s.sweepAngles()) {
            if (lineLost && Math.abs(Math.IEEEremainder(angle - holeAngle, 2 * Math.PI)) < 0.4 * Stroke.SWEEP_STEP) continue;
            Shot shot = s.guess(angle, s.pathLength);
            Eval e = s.evaluate(shot, s.holeX, s.holeY);
            if (e.holed()) return shot;
            obstacles |= e.collided();
            boolean firstShot = pathShot;
            pathShot = false;
            if (e.penalty()) {
                // Not one shot near the path's and the hole's directions comes to rest: water or
                // the edge cuts every way at this speed, and the lay-up search takes over.
                if (++lost >= SWEEP_ALL_LOST && candidates.isEmpty()) return null;
                continue;
            }
            double d = s.field.at(e.restX(), e.restY());
            if (!Double.isFinite(d)) continue;
            if (firstShot && lineLost && d < 0.5 * s.pathLength && d >= Math.max(0.6, 0.25 * s.pathLength)) {
                // The sweep's first shot, along the shortest path's first leg round the water,
                // resting on the way: the best guess there is; Broyden from it before sweeping on.
                s.sim.phase("refine");
                Attempt a = s.solveHole(shot, e);
                if (a.holed()) return a.shot();
                s.sim.phase("sweep");
            }
            if (!reachTested && shot.speed() >= s.sim.maxSpeed() * 0.999) {
                // A maximum-speed shot along the way that stops far short: the hole is out of reach.
                reachTested = true;
                if (d > 0.3 * s.pathLength && s.field.at(s.px, s.py) - d < 0.8 * s.pathLength) return null;
            }
            candidates.add(new Candidate(shot, d));
            if (d < Math.max(0.6, 0.25 * s.pathLength)) {
                promising.add(new double[] {angle, d});
                s.sim.phase("refine");
                Attempt a = s.solveHole(shot, e);
                if (a.holed()) return a.shot();
                s.sim.phase("sweep");
            }
        }
        // The best three sweep shots start Broyden once more only where shots hit obstacles: on
        // open courses they are the ones that were not promising (2 m and more off) and never
        // holed on the suite (about 40 simulations each time); among obstacles their resting
        // probes feed the lay-up choice (without them maze-a takes 6 strokes instead of 5).
        if (obstacles) {
            candidates.sort((x, y) -> Double.compare(x.distance(), y.distance()));
            s.sim.phase("refine");
            for (int i = 0; i < Math.min(3, candidates.size()); i++) {
                Attempt a = s.solveHole(candidates.get(i).shot(), null);
                if (a.holed()) return a.shot();
            }
        }
        return obstacles ? fineSweep(promising) : null;
    }

    /**
     * Obstacles (a tree field) leave corridors narrower than the coarse sweep's step between
     * shots that hit them: the rest point is continuous inside a corridor and jumps at its
     * edges (a shot that caroms off a trunk into the hole has one tree to hit, on one side),
     * so neither the sweep nor Broyden from its shots sees one. When some sweep shot hit an
     * obstacle: around each promising sweep shot (rest point near the hole), nearest first,
     * directions FINE_STEP apart over one coarse step either side; a shot stopping within
     * 0.6 m of the hole starts Broyden. At most FINE_PROBES shots.
     */
    Shot fineSweep(List<double[]> promising) {
        s.sim.phase("fine sweep");
        promising.sort((a, b) -> Double.compare(a[1], b[1]));
        List<Double> tried = new ArrayList<>();
        int probes = 0;
        for (double[] centre : promising) {
            for (int k = 1; k * FINE_STEP < Stroke.SWEEP_STEP + 1e-9; k++) {
                for (int sign : new int[] {1, -1}) {
                    double angle = centre[0] + sign * k * FINE_STEP;
                    boolean duplicate = false;
                    for (double t : tried) {
                        if (Math.abs(Math.IEEEremainder(angle - t, 2 * Math.PI)) < 0.5 * FINE_STEP) duplicate = true;
                    }
                    if (duplicate) continue;
                    tried.add(angle);
                    if (++probes > FINE_PROBES) return null;
                    Shot shot = s.guess(angle, s.pathLength);
                    Eval e = s.evaluate(shot, s.holeX, s.holeY);
                    if (e.holed()) return shot;
                    if (e.penalty()) continue;
                    double d = s.field.at(e.restX(), e.restY());
                    if (Double.isFinite(d) && d < 0.6) {
                        s.sim.phase("refine");
                        Attempt a = s.solveHole(shot, e);
                        if (a.holed()) return a.shot();
                        s.sim.phase("fine sweep");
                    }
                }
            }
        }
        return null;
    }

    /**
     * Bank shots off the straight faces of walls and boxes: the hole mirrored in a face (moved
     * out by the ball's radius) gives the direction, the bank point must lie on the face with
     * both legs clear of obstacles, and the speed comes from the energy on both legs with the
     * normal speed scaled by the restitution at the bounce. Broyden starts from there with the
     * flat Jacobian mirrored in the face (after the bounce a shot turned left ends up right).
     * The shortest few bank lines are tried.
     */
    Shot bankShot() {
        List<double[]> lines = new ArrayList<>();
        double mu = Math.max(s.world.friction().kinetic(s.px, s.py), SpeedGuess.MIN_FRICTION);
        for (double[] f : BankFaces.of(s.world)) {
            double nx = f[4], ny = f[5];
            double ball = (s.px - f[0]) * nx + (s.py - f[1]) * ny, hole = (s.holeX - f[0]) * nx + (s.holeY - f[1]) * ny;
            if (ball <= 0.05 || hole <= 0.05) continue;
            // The mirrored hole, and where the line to it meets the face.
            double mx = s.holeX - 2 * hole * nx, my = s.holeY - 2 * hole * ny;
            double t = ball / (ball + hole);
            double bx = s.px + t * (mx - s.px), by = s.py + t * (my - s.py);
            double fx = f[2] - f[0], fy = f[3] - f[1], faceLength = Math.hypot(fx, fy);
            double along = ((bx - f[0]) * fx + (by - f[1]) * fy) / faceLength;
            if (along < 0.05 || along > faceLength - 0.05) continue;
            double l1 = Math.hypot(bx - s.px, by - s.py), l2 = Math.hypot(s.holeX - bx, s.holeY - by);
            // Both legs clear of obstacles up to a little before the bounce (water is Broyden's business).
            double back = Math.min(0.15, 0.5 * Math.min(l1, l2));
            double ax = bx + back * nx, ay = by + back * ny;
            if (!s.grid.clearLine(s.px, s.py, ax, ay, 0, 0) || !s.grid.clearLine(ax, ay, s.holeX, s.holeY, 0, 0)) continue;
            double sinIn = ball / Math.max(Math.hypot(bx - s.px, by - s.py), 1e-9);
            double kept = (1 - sinIn * sinIn) + f[6] * f[6] * sinIn * sinIn;
            double hb = s.world.terrain().height(bx, by);
            double after = SpeedGuess.speedSquared(s.gravity, mu, l2, s.world.terrain().height(s.holeX, s.holeY) - hb);
            double v2 = Math.max(after, 0.01) / Math.max(kept, 0.05)
                    + SpeedGuess.speedSquared(s.gravity, mu, l1, hb - s.world.terrain().height(s.px, s.py));
            if (v2 <= 0 || Math.sqrt(v2) > 1.05 * s.sim.maxSpeed()) continue;
            lines.add(new double[] {l1 + l2, Math.atan2(my - s.py, mx - s.px), Math.sqrt(v2), nx, ny});
        }
        lines.sort((a, b) -> Double.compare(a[0], b[0]));
        for (int i = 0; i < Math.min(BANK_TRIES, lines.size()); i++) {
            double[] l = lines.get(i);
            double[] mirror = {l[3], l[4]};
            // The hills bend the legs, so the geometric line may end in water: a small fan of
            // directions around it, outward from the line; a bank shot resting near the hole starts Broyden.
            int starts = 0;
            for (int k = 0; k <= BANK_FAN && starts < 2; k++) {
                for (int sign : new int[] {1, -1}) {
                    if (k == 0 && sign < 0) continue;
                    Shot shot = s.sim.limit(Shot.polar(l[1] + sign * k * BANK_FAN_STEP, l[2]));
                    Eval e = s.evaluate(shot, s.holeX, s.holeY);
                    if (e.holed()) return shot;
                    if (e.penalty() || !e.collided()) continue;
                    double d = s.field.at(e.restX(), e.restY());
                    if (!(d < Math.max(1.0, 0.25 * l[0]))) continue;
                    starts++;
                    Attempt a = s.capture ? s.solveHole(shot, e)
                            : s.broydenTo(shot, e, s.holeX, s.holeY, 12, s.tolerance, true, mirror);
                    if (a.holed()) return a.shot();
                    break;
                }
            }
        }
        return null;
    }
}
