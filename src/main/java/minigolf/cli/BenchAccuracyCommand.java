package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import minigolf.physics.Integrator;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import minigolf.physics.reference.Conditioning;
import minigolf.physics.reference.ReferenceResult;
import minigolf.physics.reference.ReferenceSimulator;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "bench-accuracy",
        description = {"Compares end points of random shots at the chosen integrator and step with an independent "
                + "reference (minigolf.physics.reference: adaptive Dormand-Prince 5(4) with its own event location "
                + "and stop rule, sharing no stepping code with the engine).",
                "Shots the reference does not cover (a ball left leaning on a wall) are counted in 'notCovered' and left "
                        + "out of the errors; so are ill-conditioned shots, whose reference end point moves by more than "
                        + "1 mm when a velocity component changes by 1e-7 m/s ('illConditioned', listed in "
                        + "'illConditionedShots'): they have no 1 mm answer. 'compared' counts the rest."})
final class BenchAccuracyCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--shots", paramLabel = "N", description = "Random shots from the start to compare (default: ${DEFAULT-VALUE}).")
    int shots = 100;

    @Option(names = "--integrator", paramLabel = "rk4|rk2|euler", description = "Integrator under test (default: ${DEFAULT-VALUE}).")
    String integrator = "rk4";

    @Option(names = "--dt", paramLabel = "S", description = "Time step under test in seconds, 1/1000 to 1/30 (default: ${DEFAULT-VALUE}, i.e. 1/60 s).")
    double dt = SimulationSettings.DEFAULT_DT;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of the random shots (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Override
    public Integer call() {
        Integrator chosen = Integrator.fromName(integrator);
        if (chosen == null) throw new UserError("--integrator: expected rk4, rk2 or euler, got '" + integrator + "'");
        if (shots < 1) throw new UserError("--shots: must be at least 1, got " + shots);
        if (SimulationSettings.dtProblem(dt) != null) throw new UserError("--dt: " + SimulationSettings.dtProblem(dt));
        World world = CourseArgument.load(course);
        Simulator tested = new Simulator(world, SimulationSettings.DEFAULT.withIntegrator(chosen).withDt(dt));
        ReferenceSimulator reference = new ReferenceSimulator(world);
        RandomShots random = new RandomShots(seed, world.physics().maxSpeed());
        double[] errors = new double[shots];
        int covered = 0, compared = 0, sameOutcome = 0;
        ArrayNode illConditioned = Json.array();
        Map<String, Integer> notCovered = new TreeMap<>();
        ObjectNode worst = null;
        double worstError = -1;
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        // With moving obstacles each shot is played at a random moment of their longest period.
        double period = 0;
        for (var o : world.course().obstacles()) {
            if (o instanceof minigolf.course.Obstacle.Moving m) period = Math.max(period, m.motion().period());
        }
        for (int i = 0; i < shots; i++) {
            double[] v = random.next();
            double clock = period > 0 ? random.clock(period) : 0;
            ReferenceResult b = reference.simulateAt(clock, x0, y0, v[0], v[1], 0);
            if (!b.covered()) {
                notCovered.merge(b.note(), 1, Integer::sum);
                continue;
            }
            covered++;
            ShotResult a = tested.simulateAt(clock, x0, y0, v[0], v[1], 0);
            double error = Math.hypot(a.endX() - b.endX(), a.endY() - b.endY());
            double spread = Conditioning.spread(reference, clock, x0, y0, v[0], v[1], b);
            if (Conditioning.illConditioned(spread)) {
                ObjectNode shot = illConditioned.addObject();
                shot.put("shot", i);
                shot.set("velocity", Json.array(v[0], v[1]));
                if (Double.isFinite(spread)) {
                    shot.put("spreadMm", spread * 1e3);
                } else {
                    shot.putNull("spreadMm");
                    shot.put("note", "a perturbed shot is not covered");
                }
                shot.put("errorMm", error * 1e3);
                continue;
            }
            if (a.outcome() == b.outcome()) sameOutcome++;
            errors[compared++] = error;
            if (error > worstError) {
                worstError = error;
                worst = worstShot(i, v, a, b, error);
                if (period > 0) worst.put("clock", clock);
            }
        }
        double[] sorted = Arrays.copyOf(errors, compared);
        Arrays.sort(sorted);
        int within = 0;
        for (double e : sorted) if (e <= 1e-3) within++;
        ObjectNode out = Json.object();
        out.put("course", world.course().name());
        out.put("shots", shots);
        out.put("integrator", chosen.cliName());
        out.put("dt", dt);
        out.put("reference", ReferenceSimulator.description());
        out.put("covered", covered);
        ObjectNode reasons = out.putObject("notCovered");
        notCovered.forEach(reasons::put);
        out.put("illConditioned", illConditioned.size());
        out.put("compared", compared);
        putMm(out, "medianErrorMm", sorted, 0.5);
        putMm(out, "p90ErrorMm", sorted, 0.9);
        putMm(out, "p999ErrorMm", sorted, 0.999);
        putMm(out, "maxErrorMm", sorted, 1);
        out.put("withinOneMm", within);
        out.put("sameOutcome", sameOutcome);
        if (worst != null) out.set("worst", worst);
        out.set("illConditionedShots", illConditioned);
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    /** The nearest-rank percentile of the compared shots' errors, in mm; null when no shot was compared. */
    private static void putMm(ObjectNode out, String key, double[] sorted, double fraction) {
        if (sorted.length == 0) {
            out.putNull(key);
            return;
        }
        int rank = (int) Math.ceil(fraction * sorted.length);
        out.put(key, sorted[Math.max(0, Math.min(sorted.length - 1, rank - 1))] * 1e3);
    }

    private static ObjectNode worstShot(int shot, double[] v, ShotResult engine, ReferenceResult reference, double error) {
        ObjectNode worst = Json.object();
        worst.put("shot", shot);
        worst.set("velocity", Json.array(v[0], v[1]));
        worst.put("errorMm", error * 1e3);
        ObjectNode e = worst.putObject("engine");
        e.put("outcome", engine.outcome().jsonName());
        e.set("end", Json.array(engine.endX(), engine.endY()));
        ObjectNode r = worst.putObject("reference");
        r.put("outcome", reference.outcome().jsonName());
        r.set("end", Json.array(reference.endX(), reference.endY()));
        r.put("launches", reference.launches());
        r.put("contacts", reference.contacts());
        return worst;
    }
}
