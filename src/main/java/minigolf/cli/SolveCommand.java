package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.Bots;
import minigolf.bot.CancellationToken;
import minigolf.bot.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

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

    @Override
    public Integer call() {
        Bot chosen = BotArguments.bot(bot);
        if (maxStrokes < 1) throw new UserError("--max-strokes: must be at least 1, got " + maxStrokes);
        if (budget < 1) throw new UserError("--budget: must be at least 1, got " + budget);
        BotArguments.timeLimit(timeLimit);
        World world = CourseArgument.load(course);
        Playthrough.Result result = Playthrough.play(chosen, world, SimulationSettings.DEFAULT, maxStrokes, budget,
                seed, CancellationToken.withTimeLimit(timeLimit), BotProgress.NONE);
        spec.commandLine().getOut().println(Json.write(toJson(chosen.name(), world.course().name(), result)));
        return 0;
    }

    static ObjectNode toJson(String botName, String courseName, Playthrough.Result result) {
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
            shot.set("velocity", s.shot().isPutt() ? Json.array(s.shot().vx(), s.shot().vy())
                    : Json.array(s.shot().vx(), s.shot().vy(), s.shot().vz()));
            shot.put("outcome", s.result().outcome().jsonName());
            shot.set("end", Json.array(s.result().endX(), s.result().endY()));
            shot.put("simulations", s.simulations());
        }
        return out;
    }
}
