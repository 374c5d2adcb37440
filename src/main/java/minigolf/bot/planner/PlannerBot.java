package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.map.DistanceField;
import minigolf.bot.search.SearchBot;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * Our bot, the game's default (docs/bots.md). Its full search, from a budget of
 * {@link #FULL_SEARCH_BUDGET} and in {@code planner-aces} at any budget, adds {@link DenseSweep} on
 * the first stroke, two strokes chosen on the {@link OnePuttMap} ({@link MapTwoStrokes}), the wide
 * lay-up sweep and the friction-aware distance field. Per stroke:
 * <ol>
 * <li>If the hole is within about a maximum-speed roll (along the water-avoiding distance):
 *     Broyden's quasi-Newton method from the physics guess straight at the hole, aimed at the middle
 *     of the success region, not its edge: the rest point on the centre (rest rule), or the ball
 *     crossing the centre at half the capture speed with no lateral miss (capture rule; probed in
 *     a world that differs only in the hole rule, confirmed in the real one).</li>
 * <li>Bank shots off walls and boxes: the hole mirrored in a face gives the line, Broyden the shot.</li>
 * <li>If that fails (water in the way): a sweep of directions around the shortest path's and the
 *     hole's direction at the physics speed for the path's length, scored on the distance field;
 *     promising rest points start Broyden again.</li>
 * <li>Two strokes: a look-ahead (does one putt hole from there?) from the search's resting probes,
 *     the stroke plan's one-putt lay-up, then a lay-up sweep at several speeds.</li>
 * <li>No hole-in-one: a lay-up chosen by the stroke plan (fewest straight putts to the hole over
 *     cells clear of water), with a look-ahead that the last lay-up really holes next; when that
 *     lay-up leaves 3 or more strokes, a sweep all round at several speeds plays the rest point
 *     nearest the hole instead (banks and curves get further than straight putts); failing all,
 *     a point along the shortest path; last, the shot resting nearest the hole.</li>
 * <li>Cycle memory ({@link CycleGuard}): a chosen stroke that leads back to a position played
 *     from (or is lost) is replaced by the best known shot that makes progress.</li>
 * </ol>
 * The stages are classes of their own ({@link HoleInOne}: 1-3, {@link TwoStrokes}: 4,
 * {@link Layup}: 5) sharing one {@link Stroke} (the ball, the probes so far, the solvers); this
 * class holds what lasts between strokes (the maps, the stroke plan, the look-ahead's solutions,
 * the positions played from). The full search ends its two-stroke stages with a bounded brute-force
 * search ({@link TwoStrokeSearch}) where the budget is large; failing that, and far from the hole on
 * the first stroke, it plays a landing from which two strokes are found ({@link ThreeStrokes}).
 */
public final class PlannerBot extends SearchBot {

    /** Built at the first request, when the budget decides the search ({@link #chooseSearch}). */
    private CourseMaps maps;
    /** The positions played from this game: no stroke may lead back to one. */
    private final CycleGuard cycles = new CycleGuard();
    /** Simulations this game's {@link AceLayup} look-aheads have used (the quick plan on putts-only courses). */
    private long aceLayupSpent;
    /** Shots the look-ahead found holing from a lay-up's rest point: reused when the ball is there. */
    private final List<Solved> solved = new ArrayList<>();
    private World planWorld;
    private StrokePlan plan;
    private World mapWorld;
    private OnePuttMap onePutt;
    private World probeSource;
    private World probeWorld;

    /**
     * From this budget on the planner searches fully (planner-aces' stages and the two-stroke
     * search), which costs 2,000-7,000 simulations on a bench course and up to 300,000 where the
     * two-stroke search runs: a small share of such a budget. Below it (the game's and
     * {@code experiment}'s 20,000) it plays the quick plan; the bench suite's strokes and simulations
     * are those of the quick plan there.
     */
    public static final long FULL_SEARCH_BUDGET = 500_000;

    /** {@code planner-aces}: the full search whatever the budget. */
    private final boolean alwaysFull;
    /** Whether this game searches fully: the dense sweep, the one-putt map's two strokes, the two-stroke search. */
    private boolean fullSearch;
    /** Null: the friction-aware field with the full search, the plain one without ({@link #chooseSearch}). */
    private final Boolean frictionAware;

    /** The game's default: the quick plan, or the full search where the budget is large ({@link #FULL_SEARCH_BUDGET}). */
    public PlannerBot() {
        this(false);
    }

    /**
     * With {@code alwaysFull} ({@code planner-aces}) the full search at any budget. The full search
     * routes on the friction-aware field, the quick plan on the plain one (on the tuning tile
     * courses, sand patches, the aware field cost the quick plan a stroke on one course of 24 and
     * gained none; the full search's strokes were the same with either).
     */
    public PlannerBot(boolean alwaysFull) {
        this.alwaysFull = alwaysFull;
        this.frictionAware = null;
    }

    /** With {@code frictionAware} the distance field weighs each metre by the ground's friction ({@link CourseMaps}). */
    public PlannerBot(boolean alwaysFull, boolean frictionAware) {
        this.alwaysFull = alwaysFull;
        this.frictionAware = frictionAware;
    }

    /** -Dminigolf.plainField=true: the full search on the plain field too, for comparison. */
    static final boolean FRICTION_AWARE = !Boolean.getBoolean("minigolf.plainField");

    /** At the game's first request: the full search or the quick plan, by the budget the game has. */
    private void chooseSearch(BotRequest request) {
        if (maps != null) return;
        fullSearch = alwaysFull || request.simulator().remaining() >= FULL_SEARCH_BUDGET;
        maps = new CourseMaps(frictionAware != null ? frictionAware : fullSearch && FRICTION_AWARE);
    }

    /** Whether this game searches fully (decided at its first request; false before it). */
    public boolean searchesFully() {
        return fullSearch;
    }

    @Override
    public String name() {
        return alwaysFull ? "planner-aces" : "planner";
    }

    @Override
    protected CountingSimulator.ShotScore scoreFor(BotRequest request) {
        chooseSearch(request);
        maps.prepare(request.world(), request.token());
        DistanceField field = maps.toHole();
        return r -> {
            if (r.outcome() == Outcome.HOLED) return -1;
            if (r.outcome().isPenalty()) return 1e9;
            double d = field.at(r.endX(), r.endY());
            return Double.isFinite(d) ? d : 1e8;
        };
    }

    /** The planner chips in its own stages (where cut off, and with its look-ahead). */
    @Override
    protected boolean chipsWhenCutOff() {
        return false;
    }

    @Override
    protected Shot search(BotRequest request) {
        World world = request.world();
        CountingSimulator sim = request.simulator();
        double px = request.ballX(), py = request.ballY();
        chooseSearch(request);
        maps.prepare(world, request.token());
        cycles.visit(world, px, py, request.strokesTaken());
        if (request.strokesTaken() == 0) aceLayupSpent = 0;
        for (Solved k : solved) {
            // The lay-up came to rest exactly where the look-ahead holed out from: its shot, no new simulation.
            if (k.world() == world && k.x() == px && k.y() == py) return k.shot();
        }
        Stroke stroke = new Stroke(solved, sim, probeFor(sim), maps, px, py, () -> planFor(world, request));
        // The route it intends, for the game's and the editor's drawing; straight at the hole when cut off.
        sim.showPlan(stroke.path.isEmpty() ? List.of(new double[] {px, py}, new double[] {stroke.holeX, stroke.holeY})
                : stroke.path);
        Shot chosen = sim.limit(choose(request, stroke));
        // No stroke leads back (to a position played from, or lost): the engine is deterministic, so
        // where the chosen shot ends is known, usually without a new simulation.
        ShotResult result = sim.knownResult(chosen);
        if (result == null) result = sim.simulate(px, py, chosen);
        CountingSimulator.ShotScore score = scoreFor(request);
        Shot better = cycles.choose(chosen, result, sim.knownResults(), score);
        if (better != null) return better;
        sim.phase("progress");
        new Layup(stroke).progressSweep();
        better = cycles.choose(chosen, result, sim.knownResults(), score);
        return better != null ? better : chosen;
    }

    /** The stages in order (class comment); the first that finds its shot ends the search. */
    private Shot choose(BotRequest request, Stroke stroke) {
        World world = request.world();
        CountingSimulator sim = request.simulator();

        if (!Double.isFinite(stroke.field.at(stroke.px, stroke.py))) {
            // No way along the ground (a green ringed by water, walls round the hole): through the air.
            sim.phase("chip");
            Shot chip = new Chip(stroke).search();
            if (chip != null) return chip;
        }
        double reach = stroke.maxRoll();
        double pathLength = stroke.pathLength;
        Planned planned = null;
        if (Double.isFinite(pathLength) && pathLength <= 1.3 * reach) {
            sim.phase("direct");
            Shot shot = new HoleInOne(stroke).holeInOne();
            if (shot != null) return shot;
            MapTwoStrokes mapLayups = fullSearch ? new MapTwoStrokes(stroke, onePuttMap(stroke)) : null;
            DenseSweep dense = null;
            if (fullSearch ? request.strokesTaken() == 0 : sweepsAllRound(world)) {
                // Search all round, densely, before settling for two: the full search on the first
                // stroke (its paths also give the one-putt map's lay-ups their targets), the quick
                // plan on every stroke to a capture hole (sweepsAllRound).
                dense = new DenseSweep(stroke, mapLayups);
                shot = dense.holeInOne();
                if (shot != null) return shot;
            }
            sim.phase("two strokes");
            TwoStrokes twoStrokes = new TwoStrokes(stroke);
            shot = twoStrokes.twoStrokes();
            if (shot != null) return shot;
            if (mapLayups != null && mapLayups.hasTargets()) {
                // The dense sweep's paths gave the targets: the look-ahead from them costs little.
                shot = mapLayups.search();
                if (shot != null) return shot;
            }
            // The plan's one-putt lay-up, when the look-ahead confirms it, before the costlier sweep.
            planned = new Layup(stroke).plannedLayup();
            if (planned != null && planned.verified()) return planned.shot();
            if (mapLayups != null && !mapLayups.hasTargets()) {
                shot = mapLayups.search();
                if (shot != null) return shot;
            }
            // The sweep looks for two strokes: worth it when the plan sees no lay-up or a one-putt one.
            if (planned == null || planned.strokesLeft() <= 1) {
                shot = twoStrokes.layupSweep();
                if (shot != null) return shot;
            }
            if (!fullSearch && dense != null) {
                shot = aceLayup(stroke, dense);
                if (shot != null) return shot;
            }
            if (fullSearch) {
                shot = twoStrokes.wideLayupSweep();
                if (shot != null) return shot;
                if (request.strokesTaken() == 0) {
                    // On the first stroke only: later ones gained no stroke on the tuning sets and cost more.
                    shot = mapLayups.deepLookAhead(MapTwoStrokes.DEEP);
                    if (shot != null) return shot;
                }
                // Last: many landings, each with a brute-force putt search (only where the budget is
                // large); on later strokes too (tuning 777-27: 4 -> 3), each within its simulations (SearchBounds).
                TwoStrokeSearch search = new TwoStrokeSearch(stroke, onePuttMap(stroke));
                shot = search.search();
                if (shot != null) return shot;
                // No two strokes: of the search's landings, one from which two are found (ThreeStrokes).
                shot = new ThreeStrokes(stroke, onePuttMap(stroke)).search(search.landings(), search.screened());
                if (shot != null) return shot;
            }
        }
        if (!fullSearch && sweepsAllRound(world) && !(Double.isFinite(pathLength) && pathLength <= 1.3 * reach)) {
            // Far from a capture hole (or no way along the ground): a shot may still get there by
            // cushions, pushes or a teleport, which no ground path sees (the classic tracks).
            sim.phase("direct");
            DenseSweep dense = new DenseSweep(stroke);
            Shot shot = dense.holeInOne();
            if (shot != null) return shot;
            shot = aceLayup(stroke, dense);
            if (shot != null) return shot;
        }
        if (fullSearch && request.strokesTaken() == 0 && Double.isFinite(pathLength) && pathLength > 1.3 * reach
                && TwoStrokeSearch.bounds(sim).affordable()) {
            // Far from the hole on the first stroke, where the budget is large (the map is traced only then):
            // a landing from which two strokes are found (ThreeStrokes), among the landings of the two-stroke
            // search's grid of first strokes.
            TwoStrokeSearch grid = new TwoStrokeSearch(stroke, onePuttMap(stroke));
            Shot shot = grid.sweepLandings();
            if (shot != null) return shot;
            shot = new ThreeStrokes(stroke, onePuttMap(stroke)).search(grid.landings());
            if (shot != null) return shot;
        }
        sim.phase("lay-up");
        Shot layup = new Layup(stroke).layup(reach, planned);
        if (layup != null) return layup;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(world, request.ballX(), request.ballY());
    }

    /** The quick plan's look-ahead sweeps ({@link AceLayup}), within this game's share of the budget. */
    private Shot aceLayup(Stroke stroke, DenseSweep dense) {
        long allowance = (long) (AceLayup.SHARE * stroke.sim.budget()) - aceLayupSpent;
        if (allowance <= 0) return null;
        AceLayup search = new AceLayup(stroke, allowance);
        Shot shot = search.search(dense.rests());
        aceLayupSpent += search.spent();
        return shot;
    }

    /**
     * Whether the quick plan sweeps all round ({@link DenseSweep}) on each stroke: on putts-only
     * courses (the imported classic tracks) with a capture hole, any shot whose path crosses it
     * drops, so a sweep of full-speed shots finds every line through the hole, however many
     * cushions, pushes and teleports it takes (on 55 of the classic sample where the planner took
     * more strokes than the best human, the sweep on the first stroke only left none at the best
     * score, on every stroke 9). Other courses keep the plan the levels were calibrated on.
     */
    static boolean sweepsAllRound(World world) {
        return world.hole().rule() == HoleRule.CAPTURE && world.physics().puttsOnly();
    }

    /** The one-putt map of this world, traced on first use. */
    private OnePuttMap onePuttMap(Stroke stroke) {
        CountingSimulator sim = stroke.sim;
        if (mapWorld != sim.world()) {
            sim.phase("one-putt map");
            onePutt = OnePuttMap.build(stroke.probe);
            mapWorld = sim.world();
        }
        return onePutt;
    }

    /**
     * The course's grid, distance field and stroke plan for this request's world, as the planner
     * keeps them between strokes (built if not yet): {@code robust} scores its draws on them.
     */
    public CourseMaps courseMaps(BotRequest request) {
        chooseSearch(request);
        maps.prepare(request.world(), request.token());
        return maps;
    }

    public StrokePlan strokePlan(BotRequest request) {
        courseMaps(request);
        return planFor(request.world(), request);
    }

    private StrokePlan planFor(World world, BotRequest request) {
        if (planWorld != world) {
            plan = new StrokePlan(world, maps.grid(), request.token());
            planWorld = world;
        }
        return plan;
    }

    private CountingSimulator probeFor(CountingSimulator sim) {
        World world = sim.world();
        if (world.hole().rule() == HoleRule.REST) return sim;
        if (probeSource != world) {
            Course c = world.course();
            List<Hole> rest = new ArrayList<>();
            for (Hole h : c.extraHoles()) rest.add(new Hole(h.position(), h.radius(), HoleRule.REST, null));
            Hole h = c.hole();
            Course probe = new Course(c.format(), c.name(), c.terrain(), c.bounds(), c.physics(), c.start(),
                    new Hole(h.position(), h.radius(), HoleRule.REST, null), c.zones(), c.obstacles(), c.pushZones(),
                    c.magnets(), c.teleports(), c.world(), rest, c.bricks());
            probeWorld = new World(probe, world.terrain()).withState(world.state());
            probeSource = world;
        }
        return sim.variant(probeWorld, true);
    }

}
