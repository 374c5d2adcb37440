package minigolf.game;

import java.nio.file.Path;
import java.util.Locale;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * A brute-force sweep of first strokes from the tee: every direction in steps of {@code 360/angles}
 * degrees times every speed in steps of {@code maxSpeed/speeds}. It counts the strokes that hole
 * (a hole in one) and picks the one with the most holing neighbours in the grid (the middle of a
 * success region, the shot least sensitive to rounding). Run as a program it prints a table for
 * round files: {@code HoleInOneSweep ROUND.json [ANGLES SPEEDS]}.
 */
final class HoleInOneSweep {
    /** The outcome of a sweep: how many of how many strokes holed, and the steadiest holing stroke (or null). */
    record Result(int holed, int total, double[] best) {
        double fraction() {
            return (double) holed / total;
        }
    }

    private HoleInOneSweep() {
    }

    static Result sweep(World world, int angles, int speeds) {
        Simulator sim = new Simulator(world, SimulationSettings.DEFAULT);
        double x = world.course().start().x(), y = world.course().start().y(), max = world.physics().maxSpeed();
        boolean[][] holed = new boolean[angles][speeds];
        int count = 0;
        for (int a = 0; a < angles; a++) {
            double t = 2 * Math.PI * a / angles;
            for (int s = 0; s < speeds; s++) {
                double v = max * (s + 1) / speeds;
                long t0 = System.nanoTime();
                minigolf.physics.ShotResult r = sim.simulate(x, y, v * Math.cos(t), v * Math.sin(t));
                holed[a][s] = r.outcome() == Outcome.HOLED;
                if (Boolean.getBoolean("slow") && System.nanoTime() - t0 > 200_000_000L) {
                    System.out.printf(Locale.ROOT, "slow: %.3f:%.3f %s t=%.1f steps=%d %.2f s%n", v * Math.cos(t), v * Math.sin(t),
                            r.outcome(), r.time(), r.steps(), (System.nanoTime() - t0) / 1e9);
                }
                if (holed[a][s]) count++;
            }
        }
        double[] best = null;
        int bestScore = -1;
        for (int a = 0; a < angles; a++) {
            for (int s = 0; s < speeds; s++) {
                if (!holed[a][s]) continue;
                int score = 0;
                for (int da = -2; da <= 2; da++) {
                    for (int ds = -2; ds <= 2; ds++) {
                        int aa = Math.floorMod(a + da, angles), ss = s + ds;
                        if (ss >= 0 && ss < speeds && holed[aa][ss]) score++;
                    }
                }
                if (score > bestScore) {
                    bestScore = score;
                    double t = 2 * Math.PI * a / angles, v = max * (s + 1) / speeds;
                    best = new double[]{v * Math.cos(t), v * Math.sin(t)};
                }
            }
        }
        return new Result(count, angles * speeds, best);
    }

    public static void main(String[] args) throws Exception {
        Round round = RoundLoader.load(Path.of(args[0]));
        String only = System.getProperty("holes");
        int angles = args.length > 1 ? Integer.parseInt(args[1]) : 720;
        int speeds = args.length > 2 ? Integer.parseInt(args[2]) : 50;
        for (int i = 0; i < round.size(); i++) {
            if (only != null && !java.util.Arrays.asList(only.split(",")).contains(String.valueOf(i + 1))) continue;
            Round.Hole h = round.hole(i);
            long t0 = System.nanoTime();
            Result r = sweep(h.world(), angles, speeds);
            System.out.printf(Locale.ROOT, "%2d %-16s par %d  holed %5d of %d (%.3f%%)  best %s  %.1f s%n", i + 1,
                    h.world().course().name(), h.par(), r.holed(), r.total(), 100 * r.fraction(),
                    r.best() == null ? "none" : String.format(Locale.ROOT, "%.17g:%.17g", r.best()[0], r.best()[1]),
                    (System.nanoTime() - t0) / 1e9);
        }
    }
}
