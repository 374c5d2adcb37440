package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import minigolf.course.PhysicsModel;
import minigolf.io.AtomicFile;
import minigolf.physics.Integrator;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "simulate", description = "Simulates one shot from the course's start and prints the result as JSON.")
final class SimulateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--velocity", required = true, paramLabel = "VX,VY[,VZ]",
            description = "The shot's velocity in m/s, e.g. 3.2,0.5 (a putt) or 3,0,2 (a chip).")
    String velocityText;

    @Option(names = "--integrator", paramLabel = "rk4|rk2|euler", description = "Integrator (default: ${DEFAULT-VALUE}).")
    String integrator = "rk4";

    @Option(names = "--dt", paramLabel = "S", description = "Time step in seconds, 1/1000 to 1/30 (default: ${DEFAULT-VALUE}, i.e. 1/60 s).")
    double dt = SimulationSettings.DEFAULT_DT;

    @Option(names = "--model", paramLabel = "classic|complete", description = "Overrides the course's physics model (default: the course's).")
    String model;

    @Option(names = "--trajectory", paramLabel = "FILE.csv", description = "Writes t,x,y,vx,vy,z,vz (s, m, m/s) for every step (default: none).")
    Path trajectory;

    @Override
    public Integer call() throws IOException {
        int components = velocityText.split(",", -1).length;
        if (components != 2 && components != 3) {
            throw new UserError("--velocity: expected 2 or 3 comma-separated numbers (VX,VY or VX,VY,VZ), got '" + velocityText + "'");
        }
        double[] velocity = Vectors.parse("--velocity", velocityText, components);
        double vz = velocity.length == 3 ? velocity[2] : 0;
        Integrator chosen = Integrator.fromName(integrator);
        if (chosen == null) throw new UserError("--integrator: expected rk4, rk2 or euler, got '" + integrator + "'");
        if (SimulationSettings.dtProblem(dt) != null) throw new UserError("--dt: " + SimulationSettings.dtProblem(dt));
        World world = CourseArgument.load(course);
        if (model != null) {
            PhysicsModel m = PhysicsModel.fromJsonName(model);
            if (m == null) throw new UserError("--model: expected classic or complete, got '" + model + "'");
            world = world.withModel(m);
        }
        Simulator simulator = new Simulator(world, SimulationSettings.DEFAULT.withIntegrator(chosen).withDt(dt));
        StringBuilder csv = trajectory == null ? null : new StringBuilder("t,x,y,vx,vy,z,vz\n");
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        if (csv != null) appendRow(csv, 0, x0, y0, world.terrain().height(x0, y0), velocity[0], velocity[1], vz);
        TrajectoryListener rows = new TrajectoryListener() {
            public void onStep(double t, double x, double y, double vx, double vy) {
            }

            public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
                if (csv != null) appendRow(csv, t, x, y, z, vx, vy, vz);
            }
        };
        ShotResult result;
        try {
            result = simulator.simulate(x0, y0, velocity[0], velocity[1], vz, rows);
        } catch (IllegalArgumentException e) {
            throw new UserError("--velocity: " + e.getMessage());
        } catch (minigolf.physics.NonFiniteMotionException e) {
            throw new UserError(course + ": " + e.getMessage());
        }
        if (csv != null) {
            try {
                AtomicFile.write(trajectory, csv.toString().getBytes(StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new UserError(trajectory + ": cannot write: " + e.getMessage());
            }
        }
        ObjectNode out = Json.object();
        out.put("outcome", result.outcome().jsonName());
        out.set("end", Json.array(result.endX(), result.endY(), result.endZ()));
        out.put("time", result.time());
        out.put("steps", result.steps());
        ArrayNode events = out.putArray("events");
        for (StrokeEvent e : result.events()) {
            ObjectNode event = events.addObject();
            event.put("t", e.t());
            event.put("type", e.type().jsonName());
            event.set("position", Json.array(e.x(), e.y(), e.z()));
        }
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    private static void appendRow(StringBuilder csv, double t, double x, double y, double z, double vx, double vy, double vz) {
        csv.append(String.format(Locale.ROOT, "%.6f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f%n", t, x, y, vx, vy, z, vz));
    }
}
