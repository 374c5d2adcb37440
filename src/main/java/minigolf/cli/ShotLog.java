package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import minigolf.bot.experiment.RunPlan;
import minigolf.bot.play.Playthrough;

/**
 * An experiment's strokes, one JSON object per finished run on one line (shots.jsonl beside
 * runs.csv): {"run", "course", "bot", "seed", "holed", "strokes", "shots": [{"velocity", "wait",
 * "outcome", "end", "simulations"}]}, {@code "wait"} the seconds a bot waited before the shot where
 * obstacles move (issue 24). Appended as runs end; a run cut off and run again may have a line twice
 * (the last one counts). Each shard folder keeps its own.
 */
final class ShotLog implements Closeable {
    static final String FILE_NAME = "shots.jsonl";

    private final Path file;

    ShotLog(Path file) {
        this.file = file;
    }

    synchronized void append(int run, RunPlan.Run description, Playthrough.Result result) throws IOException {
        ObjectNode line = Json.object();
        line.put("run", run);
        line.put("course", description.course());
        line.put("bot", description.bot());
        line.put("seed", description.seed());
        line.put("holed", result.holed());
        line.put("strokes", result.strokes());
        ArrayNode shots = line.putArray("shots");
        for (Playthrough.PlayedShot s : result.shots()) {
            ObjectNode shot = shots.addObject();
            shot.set("velocity", SolveCommand.velocity(s.shot()));
            shot.put("wait", s.intended().waitSeconds());
            shot.put("outcome", s.result().outcome().jsonName());
            shot.set("end", Json.array(s.result().endX(), s.result().endY()));
            shot.put("simulations", s.simulations());
        }
        String text = Json.write(line) + "\n";
        Files.write(file, text.getBytes(StandardCharsets.UTF_8), StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }

    @Override
    public void close() {
    }
}
