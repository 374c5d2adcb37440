package minigolf.game;

import java.util.HashMap;
import java.util.Map;
import minigolf.physics.World;

/**
 * One bot per seat per hole: the game asks the same bot for every stroke of a player's hole, so
 * what it remembers between strokes (the planner's cycle memory, its stroke plan and look-ahead
 * solutions) lasts the hole. A new hole (another world) or {@link #clear()} starts afresh. Used on
 * the render thread only; a bot is asked again only after its previous turn is done.
 */
public final class BotSeats {
    private record Seat(String bot, World world, ShotPlanner planner) {
    }

    private final Map<Integer, Seat> seats = new HashMap<>();

    /** The bot for this seat on this hole, made on first use; null when no bot has that name. */
    public ShotPlanner planner(int seat, String bot, World world) {
        Seat s = seats.get(seat);
        if (s == null || s.world() != world || !s.bot().equals(bot)) {
            ShotPlanner planner = BotCatalog.planner(bot);
            if (planner == null) return null;
            s = new Seat(bot, world, planner);
            seats.put(seat, s);
        }
        return s.planner();
    }

    /** Forgets every bot (a new game, or a cancelled turn whose worker may still be ending). */
    public void clear() {
        seats.clear();
    }
}
