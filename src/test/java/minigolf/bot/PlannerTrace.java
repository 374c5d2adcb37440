package minigolf.bot;

import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Where the planner's simulations go: plays each named bench course once and prints, per phase
 * change, how many simulations the phase before it took (a tool, not a test; run its main).
 */
public final class PlannerTrace {
    private PlannerTrace() {
    }

    public static void main(String[] args) {
        for (String course : args) {
            World world = BenchCourses.load(course);
            long[] last = {0};
            String[] phase = {"start"};
            StringBuilder out = new StringBuilder(course + ":");
            BotProgress progress = (simulations, budget, p) -> {
                if (p.equals(phase[0])) return;
                if (simulations > last[0]) out.append(' ').append(phase[0]).append('=').append(simulations - last[0]);
                last[0] = simulations;
                phase[0] = p;
            };
            Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000,
                    1, CancellationToken.none(), progress);
            if (r.simulations() > last[0]) out.append(' ').append(phase[0]).append('=').append(r.simulations() - last[0]);
            out.append(" | holed ").append(r.holed()).append(", ").append(r.strokes()).append(" strokes, ")
                    .append(r.simulations()).append(" simulations");
            System.out.println(out);
        }
    }
}
