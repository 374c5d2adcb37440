package minigolf.cli;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.course.CourseException;
import minigolf.game.ParCheck;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.io.AtomicFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "par-check",
        description = "Plays a round's holes with a medium and a pro opponent over seeds 1..N and checks each par:"
                + " medium's mean at most par + 1.5, pro's at most par, pro aces on at most a third of the seeds"
                + " (docs/worlds.md). Prints a Markdown table; exit code 1 when a hole fails.")
final class ParCheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "ROUND", description = "The round file.")
    Path round;

    @Option(names = "--medium", paramLabel = "BOT[@SIGMA]",
            description = "The medium opponent: a bot and the velocity noise its strokes get, m/s (default: ${DEFAULT-VALUE}).")
    String medium = ParCheck.MEDIUM;

    @Option(names = "--pro", paramLabel = "BOT[@SIGMA]", description = "The pro opponent (default: ${DEFAULT-VALUE}).")
    String pro = ParCheck.PRO;

    @Option(names = "--seeds", paramLabel = "N", description = "Games per hole and opponent, seeds 1..N (default: ${DEFAULT-VALUE}).")
    int seeds = 10;

    @Option(names = "--holes", paramLabel = "1,2,...", split = ",", description = "Only these holes (default: all).")
    List<Integer> holes = new ArrayList<>();

    @Option(names = "--ace-holes", paramLabel = "1,2,...", split = ",",
            description = "Holes meant as ace holes: the pro may ace them as often as it can (default: none).")
    List<Integer> aceHoles = new ArrayList<>();

    @Option(names = "--max-strokes", paramLabel = "K", description = "Most strokes a game (default: ${DEFAULT-VALUE}).")
    int maxStrokes = 10;

    @Option(names = "--budget", paramLabel = "N", description = "Most simulations a game (default: ${DEFAULT-VALUE}).")
    long budget = 60_000;

    @Option(names = "--sweep", paramLabel = "ANGLESxSPEEDS",
            description = "The grid of first strokes whose holing share is reported, 0x0 for none (default: ${DEFAULT-VALUE}).")
    String sweep = "360x30";

    @Option(names = "--threads", paramLabel = "T", description = "Holes played at once (default: ${DEFAULT-VALUE}).")
    int threads = 1;

    @Option(names = "--out", paramLabel = "FILE.md", description = "Also write the table to this file (default: none).")
    Path out;

    @Override
    public Integer call() throws Exception {
        if (seeds < 1) throw new UserError("--seeds: must be at least 1, got " + seeds);
        if (maxStrokes < 1) throw new UserError("--max-strokes: must be at least 1, got " + maxStrokes);
        if (budget < 1) throw new UserError("--budget: must be at least 1, got " + budget);
        if (threads < 1) throw new UserError("--threads: must be at least 1, got " + threads);
        String[] grid = sweep.toLowerCase(java.util.Locale.ROOT).split("x");
        int angles, speeds;
        try {
            angles = Integer.parseInt(grid[0].trim());
            speeds = Integer.parseInt(grid[1].trim());
        } catch (RuntimeException e) {
            throw new UserError("--sweep: expected ANGLESxSPEEDS such as 360x30, got '" + sweep + "'");
        }
        if (angles < 0 || speeds < 0) throw new UserError("--sweep: must not be negative, got '" + sweep + "'");
        ParCheck.Opponent m, p;
        try {
            m = ParCheck.Opponent.parse("--medium", medium);
            p = ParCheck.Opponent.parse("--pro", pro);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        Round r;
        try {
            r = RoundLoader.load(round);
        } catch (CourseException e) {
            throw new UserError(e.getMessage());
        }
        for (int h : holes) if (h < 1 || h > r.size()) throw new UserError("--holes: no hole " + h + " (the round has " + r.size() + ")");
        ParCheck.Settings settings = new ParCheck.Settings(seeds, maxStrokes, budget, angles, speeds, threads);
        List<ParCheck.HoleResult> results = ParCheck.run(r, holes, aceHoles, m, p, settings);
        String table = ParCheck.table(r.name(), results, m, p, settings);
        spec.commandLine().getOut().print(table);
        if (out != null) {
            try {
                AtomicFile.write(out, table.getBytes(StandardCharsets.UTF_8));
            } catch (java.io.IOException e) {
                throw new UserError("--out: cannot write " + out + ": " + e.getMessage());
            }
        }
        return results.stream().allMatch(ParCheck.HoleResult::passes) ? 0 : 1;
    }
}
