package minigolf.bot;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import minigolf.bot.planner.PlannerBot;

/** Every bot by its command-line name. Each call to {@link #create} gives a fresh bot (one per thread). */
public final class Bots {
    /** The game's default bot. */
    public static final String DEFAULT = "planner";

    private static final Map<String, Supplier<Bot>> FACTORIES = new LinkedHashMap<>();

    static {
        FACTORIES.put("planner", PlannerBot::new);
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
