package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;

/**
 * The full search's last try for two strokes (on any stroke), when every cheaper stage
 * found none (issue 13): a bounded brute-force search of its own. The two-stroke games the stages
 * miss often hole from one small region only (a putt off cushions near the speed limit), which no
 * lay-up aimed by the maps lands in; trying many landings is what finds them. A grid of first
 * strokes all round ({@link #DIRECTIONS} x {@link #SPEEDS}; cushions make the bank shots), their
 * rest points merged into {@link #CELL} cells so each landing area is tried once, the cells ordered
 * by promise (marked on the {@link OnePuttMap}, the cheapest putt first; then nearest the hole on
 * the distance field), and from each a brute-force putt search ({@link PuttSweep}). The first landing from which
 * one putt holes is the shot; its putt is kept for the next stroke.
 *
 * <p>Bounded in simulations ({@link SearchBounds}): at most {@link #MAX_SIMULATIONS}, leaving {@link #RESERVE} of
 * the budget to the strokes after it (so with the game's usual budget of 20,000 it does not run); every
 * simulation checks the token, so a cancel (or the caller's time limit) stops it.
 */
final class TwoStrokeSearch {
    static final int DIRECTIONS = 180;
    /** First-stroke speeds: k / SPEEDS of the maximum, k from {@link #SLOWEST} to SPEEDS. */
    static final int SPEEDS = 16;
    static final int SLOWEST = 2;
    static final double CELL = 0.25;
    static final long MAX_SIMULATIONS = 300_000;
    static final long RESERVE = 20_000;

    /** A landing: the first shot that rested in the cell, where exactly, and its promise. */
    record Landing(Shot shot, double x, double y, double promise) {
    }

    private final Stroke s;
    private final OnePuttMap map;
    private final SearchBounds bounds;
    /** Landings whose putt sweep ran, for tests and tools. */
    int tried;
    /** The first-stroke grid's landings ({@link #sweepLandings}), and whether the grid ran to its end. */
    private final List<Landing> landings = new ArrayList<>();
    private boolean swept;
    /** The landings whose putt sweep ran to its end, with the lay-up targets its paths gave. */
    private final Map<Landing, MapTwoStrokes> screened = new HashMap<>();

    TwoStrokeSearch(Stroke s, OnePuttMap map) {
        this.s = s;
        this.map = map;
        this.bounds = bounds(s.sim);
    }

    /** This search's bounds from where {@code sim} stands. */
    static SearchBounds bounds(CountingSimulator sim) {
        return new SearchBounds(sim, MAX_SIMULATIONS, RESERVE);
    }

    /** Whether the budget left leaves room for the search and the strokes after it. */
    boolean affordable() {
        return bounds.affordable();
    }

    /** The first stroke of a two-stroke game (its putt kept in {@code s.solved}), a hole-in-one, or null. */
    Shot search() {
        if (!affordable()) return null;
        Shot holed = sweepLandings();
        if (holed != null || !swept) return holed;
        s.sim.phase("two-stroke search putts");
        for (Landing l : landings) {
            if (!inBounds()) return null;
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, l.x(), l.y(), s.plan);
            tried++;
            // The putt sweep's paths also give the lay-ups from this landing (ThreeStrokes screens no more here).
            MapTwoStrokes layups = map == null ? null : new MapTwoStrokes(next, map);
            Shot putt = new PuttSweep(next, layups).holeInOne();
            if (putt != null) {
                s.solved.add(new Solved(s.world, l.x(), l.y(), putt));
                return l.shot();
            }
            if (layups != null && layups.hasTargets()) screened.put(l, layups);
        }
        return null;
    }

    /**
     * The grid of first strokes: their landings (one per cell, by promise) in {@link #landings};
     * a shot that holes, or null ({@link #swept} false when the bounds cut the grid short).
     */
    Shot sweepLandings() {
        s.sim.phase("two-stroke search");
        Set<Long> cells = new HashSet<>();
        cells.add(key(s.px, s.py));
        double vMax = s.sim.maxSpeed();
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        List<Shot> grid = new ArrayList<>();
        for (int d = 0; d < DIRECTIONS; d++) {
            double angle = holeAngle + d * 2 * Math.PI / DIRECTIONS;
            for (int k = SPEEDS; k >= SLOWEST; k--) grid.add(s.sim.limit(Shot.polar(angle, vMax * k / SPEEDS)));
        }
        boolean[] cut = {false};
        Shot holed = s.sim.simulateInOrder(s.px, s.py, grid, new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Shot shot) {
                return shot;
            }

            @Override
            public boolean mayGoOn() {
                cut[0] = !inBounds();
                return !cut[0];
            }

            @Override
            public boolean stopsAt(Shot shot, ShotResult r) {
                if (r.outcome() == Outcome.HOLED) return true;
                if (r.outcome() == Outcome.STOPPED && cells.add(key(r.endX(), r.endY()))) {
                    landings.add(new Landing(shot, r.endX(), r.endY(), promise(r.endX(), r.endY())));
                }
                return false;
            }
        });
        if (holed != null || cut[0]) return holed;
        landings.sort((a, b) -> Double.compare(a.promise(), b.promise()));
        swept = true;
        return null;
    }

    /** The grid's landings, the most promising first (empty before {@link #sweepLandings}). */
    List<Landing> landings() {
        return landings;
    }

    /** The landings whose putt sweep ran, with the lay-up targets from there its paths gave ({@link ThreeStrokes}). */
    Map<Landing, MapTwoStrokes> screened() {
        return screened;
    }

    /** Lower is tried first: marked on the one-putt map (by its putt's cost), then by the path's length to the hole. */
    private double promise(double x, double y) {
        double cost = map == null ? Double.POSITIVE_INFINITY : map.cost(x, y);
        if (Double.isFinite(cost)) return cost;
        double d = s.field.at(x, y);
        return 1e3 + (Double.isFinite(d) ? d : 1e3);
    }

    private boolean inBounds() {
        return bounds.inBounds();
    }

    private static long key(double x, double y) {
        long cx = (long) Math.floor(x / CELL), cy = (long) Math.floor(y / CELL);
        return (cx << 32) ^ (cy & 0xffffffffL);
    }
}
