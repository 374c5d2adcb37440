package minigolf.bot.friction;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.course.CourseException;
import minigolf.course.TerrainSpec;
import minigolf.course.Zone;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** A bot given hidden friction sees only the prior, and learns the truth from its strokes. */
class HiddenFrictionTest {
    /** Flat, one friction (mu_k 0.16, mu_s 0.27: not the prior), a hole 9 m away. */
    static final String FLAT = """
            {"format": 1, "name": "Flat, slow", "terrain": {"height": "0.1"},
             "bounds": {"min": [-6, -3], "max": [6, 3]},
             "physics": {"gravity": 9.81, "kineticFriction": 0.16, "staticFriction": 0.27, "maxSpeed": 6, "model": "classic"},
             "start": [-4.5, 0], "hole": {"position": [4.5, 0], "radius": 0.05, "rule": "rest"},
             "zones": [], "obstacles": []}
            """;
    /** A tilted grid with its own friction grid and a zone: every kind of friction value. */
    static final String ZONED = """
            {"format": 1, "name": "Zoned grid", "terrain": {"grid": {"origin": [-3, -3], "spacing": 1,
               "heights": [[0.1,0.2,0.3,0.4,0.5,0.6,0.7],[0.1,0.2,0.3,0.4,0.5,0.6,0.7],[0.1,0.2,0.3,0.4,0.5,0.6,0.7],
                           [0.1,0.2,0.3,0.4,0.5,0.6,0.7],[0.1,0.2,0.3,0.4,0.5,0.6,0.7],[0.1,0.2,0.3,0.4,0.5,0.6,0.7],
                           [0.1,0.2,0.3,0.4,0.5,0.6,0.7]],
               "kineticFriction": [[0.137,0.137,0.137,0.137,0.137,0.137,0.137],[0.137,0.137,0.137,0.137,0.137,0.137,0.137],
                           [0.137,0.137,0.137,0.137,0.137,0.137,0.137],[0.137,0.137,0.137,0.137,0.137,0.137,0.137],
                           [0.137,0.137,0.137,0.137,0.137,0.137,0.137],[0.137,0.137,0.137,0.137,0.137,0.137,0.137],
                           [0.137,0.137,0.137,0.137,0.137,0.137,0.137]]}},
             "bounds": {"min": [-3, -3], "max": [3, 3]},
             "physics": {"gravity": 9.81, "kineticFriction": 0.071, "staticFriction": 0.173, "maxSpeed": 5, "model": "classic"},
             "start": [-2, 0], "hole": {"position": [2, 0], "radius": 0.1, "rule": "rest"},
             "zones": [{"shape": {"type": "circle", "center": [0, 1], "radius": 0.5}, "kineticFriction": 0.553, "staticFriction": 0.617}],
             "obstacles": []}
            """;

    static World parse(String json) {
        try {
            return World.parse(json, "test");
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** Plays like the planner and keeps every request it was given. */
    static final class Watching implements Bot {
        final List<BotRequest> requests = new ArrayList<>();
        final Bot inner = new PlannerBot();

        public String name() {
            return "watching";
        }

        public Shot nextShot(BotRequest request) {
            requests.add(request);
            return inner.nextShot(request);
        }
    }

    @Test
    void theWorldABotReceivesHoldsOnlyThePrior() throws IllegalAccessException {
        World truth = parse(ZONED);
        Watching bot = new Watching();
        Playthrough.play(bot, truth, SimulationSettings.DEFAULT, 3, 20_000, 1, CancellationToken.none(), BotProgress.NONE,
                new PlayConditions(NoiseModel.NONE, true));
        assertFalse(bot.requests.isEmpty());
        Set<Double> secrets = Set.of(0.137, 0.071, 0.173, 0.553, 0.617);
        for (BotRequest r : bot.requests) {
            World seen = r.world();
            assertTrue(seen != truth && seen.course() != truth.course());
            double scale = seen.physics().kineticFriction() / FrictionPrior.KINETIC;
            assertEquals(FrictionPrior.STATIC * scale, seen.physics().staticFriction(), 1e-12);
            // Each zone has its own estimate, but only as a scale of the prior: its ratio is the prior's.
            for (Zone z : seen.course().zones()) {
                assertEquals(FrictionPrior.STATIC / FrictionPrior.KINETIC, z.staticFriction() / z.kineticFriction(), 1e-12);
            }
            TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) seen.course().terrain();
            assertNull(g.kineticFriction());
            assertNull(g.staticFriction());
            // Nothing reachable from the request is the true world, its course, or a true friction value.
            for (Object o : reachable(r)) {
                assertTrue(o != truth && o != truth.course() && o != truth.friction(), "the truth is reachable: " + o);
                if (o instanceof Double d) assertFalse(secrets.contains(d), "a true friction value is reachable: " + d);
                if (o instanceof double[] a) for (double v : a) assertFalse(secrets.contains(v), "a true value in an array");
            }
        }
    }

    /** Every object reachable from {@code root} through the fields of the project's classes, arrays and collections. */
    static Set<Object> reachable(Object root) throws IllegalAccessException {
        Set<Object> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        List<Object> todo = new ArrayList<>(List.of(root));
        while (!todo.isEmpty()) {
            Object o = todo.remove(todo.size() - 1);
            if (o == null || !seen.add(o)) continue;
            Class<?> c = o.getClass();
            if (c.isArray()) {
                if (!c.getComponentType().isPrimitive()) for (int i = 0; i < Array.getLength(o); i++) todo.add(Array.get(o, i));
            } else if (o instanceof Iterable<?> it) {
                for (Object e : it) todo.add(e);
            } else if (o instanceof Map<?, ?> m) {
                todo.addAll(m.keySet());
                todo.addAll(m.values());
            } else if (c.getName().startsWith("minigolf.")) {
                for (Class<?> k = c; k != null && k.getName().startsWith("minigolf."); k = k.getSuperclass()) {
                    for (Field f : k.getDeclaredFields()) {
                        if (Modifier.isStatic(f.getModifiers())) continue;
                        f.setAccessible(true);
                        Object v = f.get(o);
                        if (f.getType() == double.class) todo.add(v);
                        else if (!f.getType().isPrimitive()) todo.add(v);
                    }
                }
            }
        }
        return seen;
    }

    @Test
    void onAOneFrictionCourseTheEstimateIsWithinFivePercentAfterTwoStrokes() {
        World truth = parse(FLAT);
        Playthrough.Result r = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE, new PlayConditions(NoiseModel.NONE, true));
        assertTrue(r.shots().size() >= 2, "holed in one with the wrong friction?");
        double estimate = FrictionPrior.KINETIC * r.shots().get(1).frictionScale();
        System.out.printf("hidden friction, flat: after 1 stroke mu_k %.5f, after 2 %.5f (true 0.16); %d strokes, holed %b%n",
                FrictionPrior.KINETIC * r.shots().get(0).frictionScale(), estimate, r.strokes(), r.holed());
        assertEquals(0.16, estimate, 0.05 * 0.16);
        assertTrue(r.holed());
        assertTrue(r.botErrors().isEmpty(), r.botErrors().toString());
    }

    /** Maze B's layout on a slow green (courses/friction): walls stop balls short, the fit must not be fooled. */
    @Test
    void inAMazeTheEstimateIsWithinFivePercentAfterTwoStrokes() throws CourseException {
        World truth = World.load(java.nio.file.Path.of(System.getProperty("minigolf.projectDir", "."))
                .resolve("courses/friction/maze-b-slow.json"));
        Playthrough.Result r = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE, new PlayConditions(NoiseModel.NONE, true));
        assertTrue(r.holed() && r.shots().size() >= 2, r.toString());
        assertEquals(0.14, FrictionPrior.KINETIC * r.shots().get(1).frictionScale(), 0.05 * 0.14);
    }

    @Test
    void theEstimateAlsoConvergesUnderVelocityNoise() {
        World truth = parse(FLAT);
        Playthrough.Result r = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 10, 100_000, 2,
                CancellationToken.none(), BotProgress.NONE, new PlayConditions(new NoiseModel(0, 0.02), true));
        double estimate = FrictionPrior.KINETIC * r.shots().get(r.shots().size() - 1).frictionScale();
        System.out.printf("hidden friction, flat, noise 0.02 m/s: final mu_k %.5f (true 0.16) after %d strokes%n",
                estimate, r.shots().size());
        assertEquals(0.16, estimate, 0.15 * 0.16);
    }

    /**
     * A fast green (mu_k 0.06) with a band of sand across the fairway (mu_k 0.3), both at the prior's
     * ratio mu_s = 2 mu_k, so that a scale per region can be exact.
     */
    static final String SAND_BAND = """
            {"format": 1, "name": "Sand band", "terrain": {"height": "0.1"},
             "bounds": {"min": [-8, -3], "max": [8, 3]},
             "physics": {"gravity": 9.81, "kineticFriction": 0.06, "staticFriction": 0.12, "maxSpeed": 6, "model": "classic"},
             "start": [-6, 0], "hole": {"position": [6.5, 0], "radius": 0.05, "rule": "rest"},
             "zones": [{"shape": {"type": "rect", "min": [-1, -3], "max": [1, 3]}, "kineticFriction": 0.3, "staticFriction": 0.6}],
             "obstacles": []}
            """;

    /** The observation of a stroke played exactly in the true world. */
    static FrictionEstimator.Observation observed(World truth, double x, double y, double vx) {
        var r = new minigolf.physics.Simulator(truth, SimulationSettings.DEFAULT).simulate(x, y, vx, 0);
        return new FrictionEstimator.Observation(x, y, new Shot(vx, 0, 0), r.endX(), r.endY());
    }

    @Test
    void aZoneNoStrokeHasCrossedKeepsTheCommonScale() {
        World truth = parse(SAND_BAND);
        FrictionEstimator e = new FrictionEstimator(FrictionPrior.scaled(truth, 1));
        // 1.5 m/s on the green: v^2/(2 mu_k g) = 1.91 m, short of the sand.
        assertTrue(e.observe(new minigolf.bot.CountingSimulator(e.world()), observed(truth, -6, 0, 1.5),
                minigolf.physics.Outcome.STOPPED));
        double[] s = e.regionScales();
        assertEquals(0.6, s[0], 1e-4);
        assertEquals(s[0], s[1], 0.0, "the sand was never crossed: it keeps the green's scale");
    }

    @Test
    void aStrokeIntoTheSandGivesTheSandItsOwnScale() {
        World truth = parse(SAND_BAND);
        FrictionEstimator e = new FrictionEstimator(FrictionPrior.scaled(truth, 1));
        var sim = new minigolf.bot.CountingSimulator(e.world());
        e.observe(sim, observed(truth, -6, 0, 1.5), minigolf.physics.Outcome.STOPPED);
        // From (-4, 0) at 3 m/s: 2.34 m/s left at the sand's edge, then 0.93 m into the sand.
        var second = observed(truth, -4, 0, 3);
        assertTrue(second.restX() > -1 && second.restX() < 1, "the test stroke must stop in the sand: " + second);
        assertTrue(e.observe(sim, second, minigolf.physics.Outcome.STOPPED));
        double[] s = e.regionScales();
        System.out.printf("sand band: green mu_k %.5f (true 0.06), sand mu_k %.5f (true 0.3)%n",
                FrictionPrior.KINETIC * s[0], FrictionPrior.KINETIC * s[1]);
        assertEquals(0.6, s[0], 0.05 * 0.6);
        assertEquals(3.0, s[1], 0.05 * 3.0);
        // One common scale could not end both strokes where they ended.
        assertTrue(Math.abs(s[1] / s[0] - 5) < 0.5);
    }

    /**
     * Known friction, the planner aces this hole; hidden, its first stroke (planned on the prior)
     * crosses both regions and cannot tell them apart, the second (a short putt on the green) can.
     * With one common scale for both (before the per-region fit) it took 6 strokes here.
     */
    @Test
    void withASandZoneThePlannerLearnsBothFrictionsAndHolesOut() {
        World truth = parse(SAND_BAND);
        Playthrough.Result known = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 12, 200_000, 1,
                CancellationToken.none(), BotProgress.NONE, PlayConditions.NONE);
        Playthrough.Result hidden = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 12, 200_000, 1,
                CancellationToken.none(), BotProgress.NONE, new PlayConditions(NoiseModel.NONE, true));
        System.out.printf("sand band: known friction %d strokes, hidden %d strokes%n", known.strokes(), hidden.strokes());
        assertTrue(known.holed() && hidden.holed(), hidden.toString());
        assertTrue(hidden.strokes() <= known.strokes() + 2, known.strokes() + " vs " + hidden.strokes());
        assertEquals(0.06, FrictionPrior.KINETIC * hidden.shots().get(1).frictionScale(), 0.05 * 0.06);
    }

    @Test
    void bothFrictionsAreLearnedUnderVelocityNoiseToo() {
        World truth = parse(SAND_BAND);
        Playthrough.Result r = Playthrough.play(new PlannerBot(), truth, SimulationSettings.DEFAULT, 12, 200_000, 2,
                CancellationToken.none(), BotProgress.NONE, new PlayConditions(new NoiseModel(0, 0.02), true));
        Playthrough.PlayedShot last = r.shots().get(r.shots().size() - 1);
        System.out.printf("sand band, noise 0.02 m/s: green mu_k %.4f (true 0.06), sand %.4f (true 0.3), %d strokes%n",
                FrictionPrior.KINETIC * last.frictionScale(), FrictionPrior.KINETIC * last.zoneScales().get(0), r.strokes());
        assertTrue(r.holed());
        assertEquals(0.06, FrictionPrior.KINETIC * last.frictionScale(), 0.15 * 0.06);
        assertEquals(0.3, FrictionPrior.KINETIC * last.zoneScales().get(0), 0.15 * 0.3);
    }
}
