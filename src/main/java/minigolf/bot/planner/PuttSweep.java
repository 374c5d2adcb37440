package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;
import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;

/**
 * The putt search of {@link TwoStrokeSearch}: one putt that holes from a landing, found by brute
 * force where {@link DenseSweep}'s Broyden does not converge (putts off cushions near the speed
 * limit, from sand, on hills: their holing window is about 0.1-0.3 degrees by 1% of the speed).
 * Directions {@link #STEP} apart all round at {@link #SPEEDS} (on flat ground the maximum only:
 * a slower shot follows the same path); for each shot the point its path passes nearest the hole,
 * and the speed that stops a shot in that direction there, worked out forwards along the path with
 * each cushion's share of the speed² kept (exact on flat ground). Round the {@link #PASSES} nearest
 * passes a small grid of directions and speeds centred on that stopping shot.
 */
final class PuttSweep {
    static final double STEP = Math.toRadians(1);
    static final double[] FLAT_SPEEDS = {1};
    static final double[] HILL_SPEEDS = {1, 0.9, 0.8, 0.7, 0.6};
    static final double NEAR = 0.4;
    static final int PASSES = 10;
    /** The local grid: directions {@link #FINE_STEP} apart, speeds {@link #SPEED_STEP} (a fraction) apart. */
    static final double FINE_STEP = Math.toRadians(0.1);
    static final int FINE_HALF = 3;
    static final double SPEED_STEP = 0.006;
    static final int SPEED_HALF = 6;

    /** A coarse shot's nearest pass: how near, and the speed that stops a shot in its direction there. */
    record Pass(Shot shot, double distance, double stopSpeed) {
    }

    private final Stroke s;
    private final double[] speeds;
    /** Collects lay-up targets along the coarse sweep's paths (null: none), for {@link ThreeStrokes}. */
    private final MapTwoStrokes layups;

    PuttSweep(Stroke s) {
        this(s, null);
    }

    /** With {@code layups}, the coarse sweep's paths also give {@link MapTwoStrokes} its lay-up targets. */
    PuttSweep(Stroke s, MapTwoStrokes layups) {
        this.s = s;
        this.layups = layups;
        this.speeds = Flatness.isFlat(s.world) ? FLAT_SPEEDS : HILL_SPEEDS;
    }

    /** One coarse shot and its listeners: where it passes nearest the hole, the lay-ups on its path. */
    private record Coarse(Shot shot, Nearest nearest, MapTwoStrokes.Runs runs) {
    }

    /** A putt that holes out from the stroke's ball, or null. */
    Shot holeInOne() {
        double vMax = s.sim.maxSpeed() * (1 - 1e-9);
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        int directions = (int) Math.round(2 * Math.PI / STEP);
        List<Coarse> coarse = new ArrayList<>();
        for (int i = 0; i < directions; i++) {
            double angle = holeAngle + i * STEP;
            for (double f : speeds) {
                Shot shot = s.sim.limit(Shot.polar(angle, f * vMax));
                coarse.add(new Coarse(shot, new Nearest(shot), layups == null ? null : layups.tracer(shot)));
            }
        }
        List<Pass> near = new ArrayList<>();
        Coarse holed = s.sim.simulateInOrder(s.px, s.py, coarse, new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Coarse c) {
                return c.shot();
            }

            @Override
            public TrajectoryListener listener(Coarse c) {
                return c.runs() == null ? c.nearest() : Stroke.both(c.nearest(), c.runs());
            }

            @Override
            public boolean stopsAt(Coarse c, ShotResult r) {
                if (CountingSimulator.holed(r)) return true;
                if (c.runs() != null) c.runs().end(r);
                Nearest n = c.nearest();
                if (n.best < NEAR * NEAR) near.add(new Pass(c.shot(), Math.sqrt(n.best), Math.sqrt(Math.max(n.needThere, 0))));
                return false;
            }
        });
        if (holed != null) return holed.shot();
        if (layups != null) layups.swept();
        near.sort((a, b) -> Double.compare(a.distance(), b.distance()));
        List<Pass> refined = new ArrayList<>();
        for (Pass p : near) {
            if (refined.size() >= PASSES) break;
            if (refined.stream().anyMatch(q -> sameLine(q, p))) continue;
            refined.add(p);
            Shot holedHere = localGrid(p);
            if (holedHere != null) return holedHere;
        }
        return null;
    }

    /** The grid round the shot that stops where the pass was nearest, the middle first. */
    private Shot localGrid(Pass p) {
        double angle = Math.atan2(p.shot().vy(), p.shot().vx());
        List<Shot> grid = new ArrayList<>();
        for (int ring = 0; ring <= Math.max(FINE_HALF, SPEED_HALF); ring++) {
            for (int i = -Math.min(ring, FINE_HALF); i <= Math.min(ring, FINE_HALF); i++) {
                for (int j = -Math.min(ring, SPEED_HALF); j <= Math.min(ring, SPEED_HALF); j++) {
                    if (Math.max(Math.abs(i), Math.abs(j)) != ring) continue;
                    double v = p.stopSpeed() * (1 + j * SPEED_STEP);
                    if (v <= 0.01) continue;
                    grid.add(s.sim.limit(Shot.polar(angle + i * FINE_STEP, v)));
                }
            }
        }
        return s.sim.simulateInOrder(s.px, s.py, grid, CountingSimulator.InOrder.shots((shot, r) -> CountingSimulator.holed(r)));
    }

    private static boolean sameLine(Pass a, Pass b) {
        double da = Math.atan2(a.shot().vy(), a.shot().vx()) - Math.atan2(b.shot().vy(), b.shot().vx());
        return Math.abs(Math.IEEEremainder(da, 2 * Math.PI)) < 0.5 * STEP + 1e-9
                && Math.abs(a.stopSpeed() - b.stopSpeed()) < 0.02 * b.stopSpeed();
    }

    /**
     * Where a path passes nearest the hole, and the speed² a shot in its direction needs to stop
     * there: what this shot lost on the way, each cushion dividing what follows by the share of
     * the speed² it kept (as {@link MapTwoStrokes}' lay-ups work it out).
     */
    private final class Nearest implements TrajectoryListener {
        double best, needThere;
        private double lastX, lastY;
        private final StoppingNeed need;

        Nearest(Shot shot) {
            lastX = s.px;
            lastY = s.py;
            need = new StoppingNeed(shot.speed());
            best = Math.hypot(s.px - s.holeX, s.py - s.holeY);
            best *= best;
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            double v2 = vx * vx + vy * vy, previousV2 = need.lastV2();
            double needHere = need.step(v2);
            // The nearest point on the step's segment; the need interpolated along it.
            double dx = x - lastX, dy = y - lastY, len2 = dx * dx + dy * dy;
            double f = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((s.holeX - lastX) * dx + (s.holeY - lastY) * dy) / len2));
            double qx = lastX + f * dx - s.holeX, qy = lastY + f * dy - s.holeY;
            double d = qx * qx + qy * qy;
            if (d < best) {
                best = d;
                needThere = needHere - (1 - f) * (previousV2 - v2) / need.kept();
            }
            lastX = x;
            lastY = y;
        }

        @Override
        public void onEvent(StrokeEvent event) {
            if (event.type() == StrokeEvent.Type.COLLISION) {
                need.cushion(event.speedBefore(), event.speedAfter());
            }
        }
    }
}
