package minigolf.bot.planner;

import java.util.Locale;
import minigolf.bot.Shot;
import minigolf.bot.TileCourses;
import minigolf.physics.World;

/**
 * Tool (test scope): what the one-putt map says at a point of a tile course and whether the
 * look-ahead holes from there and from points round it (0.1 m apart, RADIUS round it); with
 * --dense, whether a dense hole-in-one sweep ({@link DenseSweep}) holes from each instead.
 * Arguments: SEED INDEX X Y [RADIUS] [--dense].
 */
final class MapProbe {
    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        int index = Integer.parseInt(args[1]);
        double x = Double.parseDouble(args[2]), y = Double.parseDouble(args[3]);
        double radius = args.length > 4 ? Double.parseDouble(args[4]) : 0.2;
        World w = TileCourses.generate(seed, index + 1).get(index);
        Stroke s = StagesTest.stroke(w, w.course().start().x(), w.course().start().y());
        OnePuttMap map = OnePuttMap.build(s.probe);
        MapTwoStrokes stage = new MapTwoStrokes(s, map);
        if (java.util.List.of(args).contains("--dense")) {
            for (double dx = -radius; dx <= radius + 1e-9; dx += 0.1) {
                for (double dy = -radius; dy <= radius + 1e-9; dy += 0.1) {
                    Stroke at = StagesTest.stroke(w, x + dx, y + dy);
                    Shot ace = new DenseSweep(at).holeInOne();
                    System.out.printf(Locale.ROOT, "(%.2f,%.2f) dense sweep: %s [%d sims]%n", x + dx, y + dy,
                            ace == null ? "no" : "HOLED", at.sim.count());
                }
            }
            return;
        }
        int holed = 0, marked = 0, n = 0;
        for (double dx = -radius; dx <= radius + 1e-9; dx += 0.1) {
            for (double dy = -radius; dy <= radius + 1e-9; dy += 0.1) {
                double px = x + dx, py = y + dy;
                Shot p = map.putt(px, py);
                long before = s.sim.count();
                boolean ok = stage.lookAhead(px, py);
                n++;
                if (p != null) marked++;
                if (ok) holed++;
                System.out.printf(Locale.ROOT, "(%.2f,%.2f) marked %s cost %.2f cushions %d putt %s -> %s [%d sims]%n", px, py,
                        p != null, map.cost(px, py), map.cushions(px, py),
                        p == null ? "-" : String.format(Locale.ROOT, "%.1f deg %.2f m/s", Math.toDegrees(Math.atan2(p.vy(), p.vx())), p.speed()),
                        ok ? "HOLED" : "no", s.sim.count() - before);
            }
        }
        System.out.printf(Locale.ROOT, "%d points: %d marked, %d holed%n", n, marked, holed);
    }
}
