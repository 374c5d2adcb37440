package minigolf.game;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The bots the game can seat and watch ("Test bot"), by name. Bots from minigolf.bot are adapted
 * to {@link ShotPlanner} here; each request gets a fresh planner (planners need not be thread-safe).
 */
public final class BotCatalog {
    private static final Map<String, Supplier<ShotPlanner>> PLANNERS = new LinkedHashMap<>();

    private BotCatalog() {
    }

    /** Adds a bot under its name (replacing one of the same name). */
    public static synchronized void register(String name, Supplier<ShotPlanner> factory) {
        PLANNERS.put(name, factory);
    }

    public static synchronized List<String> names() {
        return new ArrayList<>(PLANNERS.keySet());
    }

    /** A new planner for the bot with this name, or null if there is none. */
    public static synchronized ShotPlanner planner(String name) {
        Supplier<ShotPlanner> f = PLANNERS.get(name);
        return f == null ? null : f.get();
    }
}
