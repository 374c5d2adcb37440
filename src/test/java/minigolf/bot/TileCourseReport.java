package minigolf.bot;

import java.util.List;
import java.util.Locale;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Tool (test scope): the planner on generated tile courses against the exhaustive search. For
 * each course the planner plays (budget {@link #BUDGET}, at most 10 strokes, 60 s), then the exhaustive
 * search looks for a game at least one stroke shorter (so its cost stays bounded): the baseline
 * is what it finds, else the planner's own count (the search found nothing shorter, within
 * {@link #MAX_LEVELS} strokes).
 * Arguments: SEED COUNT [FIRST] [--no-search] (the planner only) [--bot=NAME] (another bot, e.g. planner-aces)
 * [--max-levels=N] (search at most N strokes deep, default {@link #MAX_LEVELS}) [--budget=N] (the bot's simulations per game).
 */
final class TileCourseReport {
    /** The search goes at most this many strokes deep (each level costs about a million simulations). */
    static final int MAX_LEVELS = 3;
    /**
     * The bot's simulation budget per game: large enough for planner-aces' two-stroke search
     * ({@code TwoStrokeSearch}, which leaves 20,000 to the later strokes); the time limit stays 60 s.
     */
    static final long BUDGET = 1_000_000;

    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        int first = args.length > 2 && !args[2].startsWith("--") ? Integer.parseInt(args[2]) : 0;
        boolean search = !List.of(args).contains("--no-search");
        String bot = List.of(args).stream().filter(a -> a.startsWith("--bot=")).map(a -> a.substring(6)).findFirst()
                .orElse("planner");
        int levels = List.of(args).stream().filter(a -> a.startsWith("--max-levels=")).map(a -> Integer.parseInt(a.substring(13)))
                .findFirst().orElse(MAX_LEVELS);
        long budget = List.of(args).stream().filter(a -> a.startsWith("--budget=")).map(a -> Long.parseLong(a.substring(9)))
                .findFirst().orElse(BUDGET);
        List<World> worlds = TileCourses.generate(seed, first + count);
        System.out.println("| course | planner holed | planner strokes | simulations | ms | fewer found by the search | search simulations | search s |");
        System.out.println("|---|---|---:|---:|---:|---|---:|---:|");
        for (int i = first; i < first + count; i++) {
            World w = worlds.get(i);
            Playthrough.Result p = Playthrough.play(Bots.create(bot), w, SimulationSettings.DEFAULT, 10, budget, 1,
                    CancellationToken.withTimeLimit(60), BotProgress.NONE);
            int cap = search ? Math.min(p.holed() ? p.strokes() - 1 : 4, levels) : 0;
            ExhaustiveStrokeSearch.Result s = cap < 1 ? null : ExhaustiveStrokeSearch.search(w,
                    new ExhaustiveStrokeSearch.Grid(0.3, 180, 24, cap, 0.6, 5));
            String fewer = !search ? "not searched" : s == null ? "– (hole-in-one)"
                    : s.strokes() == 0 ? "none in ≤ " + cap : String.valueOf(s.strokes());
            System.out.printf(Locale.ROOT, "| %s | %s | %d | %d | %.0f | %s | %d | %.1f |%n", w.course().name(),
                    p.holed() ? "yes" : "no", p.strokes(), p.simulations(), p.wallNanos() / 1e6, fewer,
                    s == null ? 0 : s.simulations(), s == null ? 0 : s.seconds());
        }
    }
}
