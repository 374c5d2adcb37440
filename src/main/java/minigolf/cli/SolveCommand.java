package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.friction.FrictionPrior;
import minigolf.bot.play.Bots;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "solve", description = "A bot plays the course from its start and prints what it did as JSON.")
final class SolveCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--bot", paramLabel = "NAME", description = "The bot (default: ${DEFAULT-VALUE}).")
    String bot = Bots.DEFAULT;

    @Option(names = "--seed", paramLabel = "S", description = "Seed for the bot's random choices (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Option(names = "--max-strokes", paramLabel = "K", description = "Stop after K shots (default: ${DEFAULT-VALUE}).")
    int maxStrokes = 10;

    @Option(names = "--budget", paramLabel = "N", description = "Most simulations for the whole game (default: ${DEFAULT-VALUE}).")
    long budget = 1_000_000;

    @Option(names = "--time-limit", paramLabel = "SECONDS",
            description = "Wall time for the whole game in seconds (default: ${DEFAULT-VALUE}): the bot then plays its best shot so far and the game stops.")
    double timeLimit = BotArguments.DEFAULT_TIME_LIMIT;

    @Option(names = "--noise-position", paramLabel = "S",
            description = "Standard deviation in metres of each stroke's start, per axis (default: ${DEFAULT-VALUE}).")
    double noisePosition = 0;

    @Option(names = "--noise-velocity", paramLabel = "S",
            description = "Standard deviation in m/s of the velocity played, per component (default: ${DEFAULT-VALUE}).")
    double noiseVelocity = 0;

    @Option(names = "--hide-friction",
            description = "The bot sees every friction value as a prior and learns the truth from its strokes (default: ${DEFAULT-VALUE}).")
    boolean hideFriction;

    @Option(names = "--threads", paramLabel = "N",
            description = "Threads the bot's sweeps run on (default: ${DEFAULT-VALUE}); the game is the same for any N.")
    int threads = 1;

    @Override
    public Integer call() {
        Bot chosen = BotArguments.bot(bot);
        if (maxStrokes < 1) throw new UserError("--max-strokes: must be at least 1, got " + maxStrokes);
        if (budget < 1) throw new UserError("--budget: must be at least 1, got " + budget);
        BotArguments.timeLimit(timeLimit);
        BotArguments.threads("--threads", threads);
        NoiseModel noise = NoiseArguments.model(noisePosition, noiseVelocity);
        World world = CourseArgument.load(course);
        PlayConditions conditions = new PlayConditions(noise, hideFriction);
        Playthrough.Result result = Playthrough.play(chosen, world, SimulationSettings.DEFAULT, maxStrokes, budget,
                seed, CancellationToken.withTimeLimit(timeLimit), BotProgress.NONE, conditions, threads);
        spec.commandLine().getOut().println(Json.write(toJson(chosen.name(), world.course().name(), result, conditions)));
        return 0;
    }

    static ObjectNode toJson(String botName, String courseName, Playthrough.Result result) {
        return toJson(botName, courseName, result, PlayConditions.NONE);
    }

    static ObjectNode toJson(String botName, String courseName, Playthrough.Result result, PlayConditions conditions) {
        ObjectNode out = Json.object();
        out.put("bot", botName);
        out.put("course", courseName);
        out.put("holed", result.holed());
        out.put("strokes", result.strokes());
        out.put("simulations", result.simulations());
        out.put("wallMs", result.wallNanos() / 1e6);
        out.put("timedOut", result.timedOut());
        ArrayNode shots = out.putArray("shots");
        for (Playthrough.PlayedShot s : result.shots()) {
            ObjectNode shot = shots.addObject();
            shot.set("velocity", velocity(s.shot()));
            shot.set("intended", velocity(s.intended()));
            // The wait before the shot (s): where obstacles move, a bot times its shot (issue 24).
            shot.put("wait", s.intended().waitSeconds());
            // With position noise the stroke did not start where the ball lay: where it did.
            if (conditions.noise().position() > 0) shot.set("start", Json.array(s.startX(), s.startY()));
            shot.put("outcome", s.result().outcome().jsonName());
            shot.set("end", Json.array(s.result().endX(), s.result().endY()));
            shot.put("simulations", s.simulations());
            if (conditions.hideFriction()) {
                ObjectNode estimate = shot.putObject("frictionEstimate");
                estimate.put("kineticFriction", FrictionPrior.KINETIC * s.frictionScale());
                estimate.put("staticFriction", FrictionPrior.STATIC * s.frictionScale());
                if (!s.zoneScales().isEmpty()) {
                    ArrayNode zones = estimate.putArray("zones");
                    for (double z : s.zoneScales()) {
                        ObjectNode zone = zones.addObject();
                        zone.put("kineticFriction", FrictionPrior.KINETIC * z);
                        zone.put("staticFriction", FrictionPrior.STATIC * z);
                    }
                }
            }
        }
        ObjectNode noise = out.putObject("noise");
        noise.put("position", conditions.noise().position());
        noise.put("velocity", conditions.noise().velocity());
        out.put("hideFriction", conditions.hideFriction());
        return out;
    }

    static ArrayNode velocity(Shot s) {
        return s.isPutt() ? Json.array(s.vx(), s.vy()) : Json.array(s.vx(), s.vy(), s.vz());
    }
}
