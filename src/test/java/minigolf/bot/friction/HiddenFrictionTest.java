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
import minigolf.bot.PlayConditions;
import minigolf.bot.Playthrough;
import minigolf.bot.Shot;
import minigolf.bot.noise.NoiseModel;
import minigolf.bot.planner.PlannerBot;
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
            for (Zone z : seen.course().zones()) assertEquals(seen.physics().kineticFriction(), z.kineticFriction());
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
}
