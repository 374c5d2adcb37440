package minigolf.bot.play;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import minigolf.bot.Bot;
import minigolf.bot.noise.RobustBot;
import minigolf.bot.path.AStarBot;
import minigolf.bot.path.GraphBot;
import minigolf.bot.path.GuidedBot;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.search.GridBot;
import minigolf.bot.search.LocalSearchBot;
import minigolf.bot.search.NewtonBot;
import minigolf.bot.search.SwarmBot;

/** Every bot by its command-line name. Each call to {@link #create} gives a fresh bot (one per thread). */
public final class Bots {
    /** The game's default bot. */
    public static final String DEFAULT = "planner";

    private static final Map<String, Supplier<Bot>> FACTORIES = new LinkedHashMap<>();

    static {
        FACTORIES.put("grid", GridBot::new);
        FACTORIES.put("local", LocalSearchBot::new);
        FACTORIES.put("newton", NewtonBot::new);
        FACTORIES.put("swarm", SwarmBot::new);
        FACTORIES.put("astar", AStarBot::new);
        FACTORIES.put("astar-newton", () -> new GuidedBot(GuidedBot.Solver.NEWTON));
        FACTORIES.put("astar-swarm", () -> new GuidedBot(GuidedBot.Solver.SWARM));
        FACTORIES.put("graph", GraphBot::new);
        FACTORIES.put("planner", PlannerBot::new);
        // The planner with a dense hole-in-one sweep on the first stroke (docs/bots.md): for real
        // courses, where aces the planner misses exist; on our suites it only costs simulations.
        FACTORIES.put("planner-aces", () -> new PlannerBot(true));
        FACTORIES.put("robust", RobustBot::new);
    }

    private Bots() {
    }

    /** The names in the order reports list them. */
    public static List<String> names() {
        return List.copyOf(FACTORIES.keySet());
    }

    /** A new bot, or null for an unknown name. */
    public static Bot create(String name) {
        Supplier<Bot> factory = FACTORIES.get(name);
        return factory == null ? null : factory.get();
    }
}
