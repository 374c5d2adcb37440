package minigolf.bot;

import java.util.List;
import java.util.Locale;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.course.Course;
import minigolf.course.Vec2;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.StrokeEvent;
import minigolf.physics.World;

/**
 * Tool (test scope): why a bot takes more strokes than the exhaustive search on a generated tile
 * course. Prints the bot's strokes and the search's shorter game, each stroke with where it
 * started and ended, its speed, the cushions it took, and whether its end sees the hole.
 * Arguments: SEED INDEX [INDEX...] [--bot=NAME] [--budget=N] (the bot's simulations per game, default 20,000)
 * [--no-search] (the bot's game only) [--from=X,Y] (both played from there instead of the course's start).
 */
final class TileDiagnosis {
    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        String bot = List.of(args).stream().filter(a -> a.startsWith("--bot=")).map(a -> a.substring(6)).findFirst()
                .orElse("planner");
        long budget = List.of(args).stream().filter(a -> a.startsWith("--budget=")).map(a -> Long.parseLong(a.substring(9)))
                .findFirst().orElse(20_000L);
        boolean search = !List.of(args).contains("--no-search");
        int max = 0;
        for (int i = 1; i < args.length; i++) if (!args[i].startsWith("--")) max = Math.max(max, Integer.parseInt(args[i]));
        List<World> worlds = TileCourses.generate(seed, max + 1);
        for (int i = 1; i < args.length; i++) {
            if (args[i].startsWith("--")) continue;
            World w = worlds.get(Integer.parseInt(args[i]));
            String from = List.of(args).stream().filter(a -> a.startsWith("--from=")).map(a -> a.substring(7)).findFirst()
                    .orElse(null);
            if (from != null) {
                // Played from another start (a rest point of some game): the course otherwise unchanged.
                String[] xy = from.split(",");
                Course c = w.course();
                w = new World(new Course(c.format(), c.name(), c.terrain(), c.bounds(), c.physics(),
                        new Vec2(Double.parseDouble(xy[0]), Double.parseDouble(xy[1])), c.hole(), c.zones(), c.obstacles()),
                        w.terrain());
            }
            CourseMaps maps = new CourseMaps();
            maps.prepare(w, CancellationToken.none());
            Simulator engine = new Simulator(w, SimulationSettings.DEFAULT);
            // The phases in order with the simulations each took (as PlannerTrace prints them).
            long[] last = {0};
            String[] phase = {"start"};
            StringBuilder phases = new StringBuilder("  phases:");
            BotProgress progress = (simulations, total, name) -> {
                if (name.equals(phase[0])) return;
                if (simulations != last[0]) phases.append(' ').append(phase[0]).append('=').append(simulations - last[0]);
                last[0] = simulations;
                phase[0] = name;
            };
            Playthrough.Result p = Playthrough.play(Bots.create(bot), w, SimulationSettings.DEFAULT, 10, budget, 1,
                    CancellationToken.withTimeLimit(60), progress);
            System.out.printf(Locale.ROOT, "%s from (%.2f,%.2f): %s %d strokes, %d simulations, %.0f ms%n", w.course().name(), w.course().start().x(), w.course().start().y(), bot,
                    p.strokes(), p.simulations(), p.wallNanos() / 1e6);
            System.out.println(phases);
            double x = w.course().start().x(), y = w.course().start().y();
            for (Playthrough.PlayedShot s : p.shots()) {
                print(w, maps, engine, x, y, s.shot().vx(), s.shot().vy(), s.simulations());
                x = s.result().endX();
                y = s.result().endY();
            }
            int cap = Math.min(p.strokes() - 1, 3);
            if (cap < 1 || !search) continue;
            ExhaustiveStrokeSearch.Result r = ExhaustiveStrokeSearch.search(w,
                    new ExhaustiveStrokeSearch.Grid(0.3, 180, 24, cap, 0.6, 5));
            System.out.printf(Locale.ROOT, "  search: %s in %.1f s%n", r.strokes() == 0 ? "none in <= " + cap : r.strokes() + " strokes", r.seconds());
            for (double[] s : r.shots()) print(w, maps, engine, s[0], s[1], s[2], s[3], 0);
        }
    }

    private static void print(World w, CourseMaps maps, Simulator engine, double x, double y, double vx, double vy, long sims) {
        ShotResult r = engine.simulate(x, y, vx, vy, 0, null);
        int cushions = 0;
        for (StrokeEvent e : r.events()) if (e.type() == StrokeEvent.Type.COLLISION) cushions++;
        double hx = w.hole().position().x(), hy = w.hole().position().y();
        boolean sees = maps.grid().clearLine(r.endX(), r.endY(), hx, hy, 0.1, 0.04);
        System.out.printf(Locale.ROOT,
                "    (%.2f,%.2f) dist %.2f -> %s (%.2f,%.2f) dist %.2f | %.1f deg %.2f m/s, %d cushions, end sees hole %s, mu %.2f  [%d sims]%n",
                x, y, maps.toHole().at(x, y), r.outcome(), r.endX(), r.endY(), maps.toHole().at(r.endX(), r.endY()),
                Math.toDegrees(Math.atan2(vy, vx)), Math.hypot(vx, vy), cushions, sees,
                w.friction().kinetic(r.endX(), r.endY()), sims);
    }
}
