package minigolf.bot.play;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import minigolf.bot.Bot;
import minigolf.bot.level.Level;
import minigolf.bot.level.LevelBot;
import minigolf.bot.noise.RobustBot;
import minigolf.bot.path.AStarBot;
import minigolf.bot.path.GraphBot;
import minigolf.bot.path.GuidedBot;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.search.GridBot;
import minigolf.bot.search.LocalSearchBot;
import minigolf.bot.search.NewtonBot;
import minigolf.bot.search.SwarmBot;

/** Every bot by its command-line name: the bots by algorithm and the opponents by level ({@link Level}). Each call to {@link #create} gives a fresh bot (one per thread). */
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
        // The planner's full search at any budget (dense hole-in-one sweep, one-putt map, ...;
        // docs/bots.md): at 20,000 a game it saves a stroke on two bench mazes, and strokes on 10 of 40
        // fresh tile courses (seed 20261127; a median of 2,554 simulations there, the planner 448).
        FACTORIES.put("planner-aces", () -> new PlannerBot(true));
        FACTORIES.put("robust", RobustBot::new);
    }

    private Bots() {
    }

    /** The bots by algorithm, in the order reports list them (what {@code experiment --bots all} plays). */
    public static List<String> names() {
        return List.copyOf(FACTORIES.keySet());
    }

    /** The opponents by level, from the easiest: {@code easy}, {@code medium}, {@code hard}, {@code pro}. */
    public static List<String> levels() {
        return Level.ids();
    }

    /** Every name {@link #create} knows: the bots by algorithm, then the levels. */
    public static List<String> allNames() {
        List<String> all = new ArrayList<>(names());
        all.addAll(levels());
        return List.copyOf(all);
    }

    /** A new bot (by algorithm or by level), or null for an unknown name. */
    public static Bot create(String name) {
        Level level = Level.byId(name);
        if (level != null) return new LevelBot(level);
        Supplier<Bot> factory = FACTORIES.get(name);
        return factory == null ? null : factory.get();
    }
}
