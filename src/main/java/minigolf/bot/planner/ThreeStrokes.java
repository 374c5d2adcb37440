package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import minigolf.bot.Shot;

/**
 * The full search's three-stroke plan (issue 13): when no two-stroke game is found, the stroke
 * is chosen among many landings by whether a two-stroke game is found from there, not by the
 * stroke plan or the distance field. On held-out tiles (20261124-36, 8675309-29) the exhaustive
 * search's three-stroke game starts with a stroke that rests no nearer the hole on the field (even
 * farther), but where a cushioned second stroke reaches a spot one putt holes from; the planner's
 * lay-up nearest the hole left a slow putt from sand or no clear line, and took 4 more.
 *
 * <p>The landings are those of {@link TwoStrokeSearch}'s grid of first strokes (already simulated,
 * one per 0.25 m cell; its own grid where that search did not run). Each landing is screened
 * cheaply: a sweep all round at the maximum speed ({@link #SCREEN_STEP} apart; on hills also at
 * 0.6 of it) traced through the {@link OnePuttMap} ({@link MapTwoStrokes}' lay-up targets: runs of
 * cells one putt holes from); where {@link TwoStrokeSearch}'s putt sweep ran from the landing, its
 * paths were traced so, and the landing costs no simulation here. The landings with the best targets
 * then get {@link MapTwoStrokes}' look-ahead (play the lay-up, Broyden the map's putt from its rest
 * point); the first landing from which it holes is the stroke, its lay-up and putt kept for the next
 * two strokes.
 *
 * <p>Bounded in simulations ({@link SearchBounds}): at most {@link #MAX_SIMULATIONS}, leaving {@link #RESERVE}
 * of the budget (so at the game's usual 20,000 it does not run).
 */
final class ThreeStrokes {
    static final double SCREEN_STEP = Math.toRadians(2);
    static final double[] HILL_SPEEDS = {1, 0.6};
    /** Landings whose targets get the look-ahead, the best screened first. */
    static final int LOOK_AHEADS = 40;
    static final long MAX_SIMULATIONS = 200_000;
    static final long RESERVE = TwoStrokeSearch.RESERVE;
    /** The screen's share of the simulations; the rest is the look-ahead's. */
    static final double SCREEN_SHARE = 0.75;

    /** A screened landing: its first stroke, where it rests, the lay-ups found from there. */
    private record Screened(TwoStrokeSearch.Landing landing, MapTwoStrokes layups, double score) {
    }

    private final Stroke s;
    private final OnePuttMap map;
    /** The whole search's bounds, and the screen's first share of them. */
    private final SearchBounds bounds, screenBounds;
    private final double[] speeds;
    /** Landings screened here (not those {@link TwoStrokeSearch} swept) and looked ahead from, for tests and tools. */
    int screened, lookedAhead;

    ThreeStrokes(Stroke s, OnePuttMap map) {
        this.s = s;
        this.map = map;
        this.bounds = new SearchBounds(s.sim, MAX_SIMULATIONS, RESERVE);
        this.screenBounds = bounds.first(SCREEN_SHARE);
        this.speeds = Flatness.isFlat(s.world) ? new double[] {1} : HILL_SPEEDS;
    }

    /** Whether the budget left leaves room for the search and the strokes after it. */
    boolean affordable() {
        return bounds.affordable();
    }

    /**
     * The first stroke of a three-stroke game among {@code landings} (its lay-up and putt kept in
     * {@code s.solved}), a shot that holes in two (the lay-up's own sweep holed: kept too), or null.
     */
    Shot search(List<TwoStrokeSearch.Landing> landings) {
        return search(landings, Map.of());
    }

    /**
     * {@link #search(List)}, the landings in {@code swept} not screened again: their lay-up
     * targets came from {@link TwoStrokeSearch}'s putt sweeps (every direction at the maximum speed and more).
     */
    Shot search(List<TwoStrokeSearch.Landing> landings, Map<TwoStrokeSearch.Landing, MapTwoStrokes> swept) {
        if (!affordable() || map == null) return null;
        s.sim.phase("three strokes screen");
        List<TwoStrokeSearch.Landing> order = new ArrayList<>(landings);
        // Nearest the hole on the field first, so a cut-short screen keeps the likelier ones.
        order.sort((a, b) -> Double.compare(distance(a), distance(b)));
        List<Screened> ranked = new ArrayList<>();
        double vMax = s.sim.maxSpeed() * (1 - 1e-9);
        int directions = (int) Math.round(2 * Math.PI / SCREEN_STEP);
        for (TwoStrokeSearch.Landing l : order) {
            if (!Double.isFinite(distance(l))) continue;
            MapTwoStrokes known = swept.get(l);
            if (known != null) {
                double score = known.bestScore();
                if (Double.isFinite(score)) ranked.add(new Screened(l, known, score));
                continue;
            }
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, l.x(), l.y(), s.plan);
            MapTwoStrokes layups = new MapTwoStrokes(next, map);
            double holeAngle = Math.atan2(s.holeY - l.y(), s.holeX - l.x());
            List<MapTwoStrokes.Runs> screen = new ArrayList<>();
            for (int i = 0; i < directions; i++) {
                for (double f : speeds) screen.add(layups.tracer(s.sim.limit(Shot.polar(holeAngle + i * SCREEN_STEP, f * vMax))));
            }
            boolean[] cut = {false};
            MapTwoStrokes.Runs holed = next.evaluateInOrder(screen, MapTwoStrokes.Runs::shot, runs -> runs, () -> {
                cut[0] = !inBounds();
                return !cut[0];
            }, (runs, e) -> {
                if (e.holed()) return true;
                runs.end(e.result());
                return false;
            });
            if (holed != null) {
                s.solved.add(new Solved(s.world, l.x(), l.y(), holed.shot()));
                return l.shot();
            }
            if (cut[0]) return lookAhead(ranked);
            layups.swept();
            screened++;
            double score = layups.bestScore();
            if (Double.isFinite(score)) ranked.add(new Screened(l, layups, score));
        }
        return lookAhead(ranked);
    }

    /** The look-ahead from the best screened landings' lay-ups; the first landing from which it holes. */
    private Shot lookAhead(List<Screened> ranked) {
        s.sim.phase("three strokes look-ahead");
        ranked.sort((a, b) -> Double.compare(a.score(), b.score()));
        for (Screened c : ranked) {
            if (lookedAhead == LOOK_AHEADS || !bounds.inBounds()) break;
            lookedAhead++;
            Shot layup = c.layups().search();
            if (layup != null) {
                s.solved.add(new Solved(s.world, c.landing().x(), c.landing().y(), layup));
                return c.landing().shot();
            }
        }
        return null;
    }

    private double distance(TwoStrokeSearch.Landing l) {
        return s.field.at(l.x(), l.y());
    }

    private boolean inBounds() {
        return screenBounds.inBounds();
    }
}
