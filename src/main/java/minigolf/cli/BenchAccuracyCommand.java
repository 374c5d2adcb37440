package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.Callable;
import minigolf.physics.Integrator;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "bench-accuracy",
        description = "Compares end points of random shots at the chosen step with a reference run (RK4 at 1e-5 s).")
final class BenchAccuracyCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--shots", paramLabel = "N", description = "Random shots from the start to compare (default: ${DEFAULT-VALUE}).")
    int shots = 100;

    @Option(names = "--integrator", paramLabel = "rk4|rk2|euler", description = "Integrator under test (default: ${DEFAULT-VALUE}).")
    String integrator = "rk4";

    @Option(names = "--dt", paramLabel = "S", description = "Time step under test in seconds (default: ${DEFAULT-VALUE}, i.e. 1/60 s).")
    double dt = SimulationSettings.DEFAULT_DT;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of the random shots (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Override
    public Integer call() {
        Integrator chosen = Integrator.fromName(integrator);
        if (chosen == null) throw new UserError("--integrator: expected rk4, rk2 or euler, got '" + integrator + "'");
        if (shots < 1) throw new UserError("--shots: must be at least 1, got " + shots);
        if (!(dt > 0) || dt > 0.1) throw new UserError("--dt: must be in (0, 0.1] seconds, got " + dt);
        World world = CourseArgument.load(course);
        Simulator tested = new Simulator(world, SimulationSettings.DEFAULT.withIntegrator(chosen).withDt(dt));
        Simulator reference = new Simulator(world, SimulationSettings.DEFAULT.withDt(1e-5));
        RandomShots random = new RandomShots(seed, world.physics().maxSpeed());
        double[] errors = new double[shots];
        int sameOutcome = 0;
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        for (int i = 0; i < shots; i++) {
            double[] v = random.next();
            ShotResult a = tested.simulate(x0, y0, v[0], v[1]);
            ShotResult b = reference.simulate(x0, y0, v[0], v[1]);
            if (a.outcome() == b.outcome()) sameOutcome++;
            errors[i] = Math.hypot(a.endX() - b.endX(), a.endY() - b.endY());
        }
        Arrays.sort(errors);
        int within = 0;
        for (double e : errors) if (e <= 1e-3) within++;
        ObjectNode out = Json.object();
        out.put("course", world.course().name());
        out.put("shots", shots);
        out.put("integrator", chosen.cliName());
        out.put("dt", dt);
        out.put("medianErrorMm", errors[shots / 2] * 1e3);
        out.put("p90ErrorMm", errors[(int) Math.min(shots - 1, Math.floor(0.9 * shots))] * 1e3);
        out.put("maxErrorMm", errors[shots - 1] * 1e3);
        out.put("withinOneMm", within);
        out.put("sameOutcome", sameOutcome);
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }
}
