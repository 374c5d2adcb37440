package minigolf.bot.level;

import java.util.List;
import java.util.Locale;
import minigolf.bot.noise.HumanError;

/**
 * The opponents a player chooses from, by how well they play: each a strategy and a human-like
 * error (docs/bots.md, "Opponents with levels"). Calibrated on human play: on a classic online
 * game's tracks, players' mean strokes are a median 3.0x the track's best score; on generated tile
 * courses {@code easy} aims at a casual player (about 2.5-3x the fewest strokes), {@code medium} at
 * 1.7-2x, {@code hard} at 1.2-1.4x, and {@code pro} is the planner itself; on the Meadowbrook round
 * (par 46) a par player should beat {@code medium} and lose to {@code hard} most of the time, {@code hard}
 * under par (not the planner's 21). Tuned on tile seeds 1001, 44706668, 36662537 and 47692372 (the
 * last three were fresh seeds of earlier checks) and the Meadowbrook round (docs/bots.md has the
 * figures and the fresh seeds they were checked on; 12273404, a fresh seed on 28 Nov, is a tuning
 * seed since).
 *
 * <ul>
 * <li>{@code easy}: the planner's line, struck 7 degrees and 23% of pace off (a casual player); from
 *     its fifth stroke on a hole it takes care: the error halves with every stroke and it lays up as
 *     the robust bot for that error (6 degrees and 20%, careful from the sixth stroke, left one
 *     game in 72 of a fresh seed not holed within 10 strokes).</li>
 * <li>{@code medium}: the noise-aware robust bot (it lays up where a bold line would likely miss),
 *     2.25 degrees and 7.75% off.</li>
 * <li>{@code hard}: the planner's line, nearly exact (0.05 degrees and 0.25% of pace) on lay-ups
 *     through narrow gaps and on putts, but an attempt at a hole in one struck with {@code medium}'s
 *     error (2.25 degrees, 7.75%): about 36 on Meadowbrook's par 46 with one ace a round (the planner
 *     21 with 15), and close to the planner on tile courses, whose fewest strokes are rarely aces.</li>
 * <li>{@code pro}: the planner, no error.</li>
 * </ul>
 *
 * @param error    the error on every stroke while the hole goes well
 * @param aceError the error on a hole's first stroke when the shot as chosen would hole (the
 *                 same as {@code error} but for {@code hard})
 * @param robust   whether the level plans for its own error (the noise-aware robust bot) or plays
 *                 the planner's line as if it were exact
 */
public enum Level {
    EASY(new HumanError(Math.toRadians(7), 0.23), new HumanError(Math.toRadians(7), 0.23), false,
            new LevelBot.Care(4, 0.5, true)),
    MEDIUM(new HumanError(Math.toRadians(2.25), 0.0775), true),
    HARD(new HumanError(Math.toRadians(0.05), 0.0025), new HumanError(Math.toRadians(2.25), 0.0775), false),
    PRO(HumanError.NONE, false);

    private final HumanError error;
    private final HumanError aceError;
    private final boolean robust;
    private final LevelBot.Care care;

    Level(HumanError error, boolean robust) {
        this(error, error, robust, LevelBot.Care.HALVING_FROM_SIXTH);
    }

    Level(HumanError error, HumanError aceError, boolean robust) {
        this(error, aceError, robust, LevelBot.Care.HALVING_FROM_SIXTH);
    }

    Level(HumanError error, HumanError aceError, boolean robust, LevelBot.Care care) {
        this.error = error;
        this.aceError = aceError;
        this.robust = robust;
        this.care = care;
    }

    /** The name on the command line and in the game's setup: {@code easy}, {@code medium}, {@code hard}, {@code pro}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    public HumanError error() {
        return error;
    }

    /** The error on a hole's first stroke when the shot as chosen would hole (an attempt at a hole in one). */
    public HumanError aceError() {
        return aceError;
    }

    public boolean robust() {
        return robust;
    }

    /** How the level takes care once its hole goes badly. */
    public LevelBot.Care care() {
        return care;
    }

    /** The level with this id, or null. */
    public static Level byId(String id) {
        for (Level level : values()) if (level.id().equals(id)) return level;
        return null;
    }

    /** The ids from the easiest to the strongest. */
    public static List<String> ids() {
        return List.of(EASY.id(), MEDIUM.id(), HARD.id(), PRO.id());
    }
}
