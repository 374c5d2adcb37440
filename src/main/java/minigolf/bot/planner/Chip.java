package minigolf.bot.planner;

import minigolf.bot.Shot;
import minigolf.bot.search.ChipSearch;

/**
 * The chip stage (issue 12): where no path along the ground reaches the hole the planner plays
 * through the air ({@link ChipSearch}, shared with the other search bots).
 */
final class Chip {
    private final Stroke s;

    Chip(Stroke stroke) {
        this.s = stroke;
    }

    /** A chip that holes, or the best resting one, or null when every chip is lost (or chips cannot be played). */
    Shot search() {
        return new ChipSearch(s.sim, s.grid, s.field, s.px, s.py).search();
    }
}
