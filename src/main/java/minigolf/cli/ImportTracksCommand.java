package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.Callable;
import minigolf.classic.ClassicScale;
import minigolf.classic.ShapeImages;
import minigolf.classic.ShapeMasks;
import minigolf.classic.TrackFormatException;
import minigolf.classic.TrackImporter;
import minigolf.game.SettingsStore;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "import-tracks",
        description = {"Imports the classic online minigolf game's .track files (format V1 and V2) under DIR:",
                "each becomes a course folder <out>/<author-name>/course.json with its wall models, and",
                "<out>/index.json lists every track with its human statistics (plays, average and best strokes).",
                "The tiles' shapes come from the game's shapes.gif and special.gif (--images, or found near",
                "DIR); without them a built-in approximation is used (see docs/classic-tracks.md).",
                "A track that cannot be imported is listed with its reason (one line on stderr) and nothing is",
                "written for it; the exit code is then 2. Prints a summary: {\"imported\", \"failed\", \"shapes\", \"out\"}."})
final class ImportTracksCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "DIR", description = "A folder of .track files (searched 8 levels deep), or one .track file.")
    Path dir;

    @Option(names = "--out", paramLabel = "DIR", description = "Where the courses and the index go (default: <config>/classic, which the game lists).")
    Path out;

    @Option(names = "--images", paramLabel = "DIR", description = "The folder with the game's shapes.gif and special.gif (default: searched near DIR).")
    Path images;

    @Option(names = "--tile", paramLabel = "METRES", description = "The size of a tile in metres (default: ${DEFAULT-VALUE}; the ball is 13/15 of a tile across).")
    double tile = ClassicScale.DEFAULT_TILE;

    @Option(names = "--no-images", description = "Use the built-in approximation of the shapes even if the images are found (default: off).")
    boolean noImages;

    @Override
    public Integer call() throws IOException {
        if (!Files.exists(dir)) throw new UserError(dir + ": no such file or folder");
        if (!(tile > 0 && tile <= 100)) throw new UserError("--tile: must be in (0, 100] metres, got " + tile);
        ShapeMasks masks;
        try {
            Optional<Path> found = images != null ? Optional.of(images) : noImages ? Optional.empty() : ShapeImages.locate(dir);
            masks = found.isPresent() ? ShapeMasks.fromImages(found.get()) : ShapeMasks.builtIn();
        } catch (TrackFormatException e) {
            throw new UserError("--images: " + e.getMessage());
        }
        Path target = out != null ? out : SettingsStore.forUser().directory().resolve("classic");
        if (Files.exists(target) && !Files.isDirectory(target)) throw new UserError("--out: " + target + " is a file, not a folder");
        TrackImporter.Result r;
        try {
            r = TrackImporter.run(dir, target, masks, new ClassicScale(tile));
        } catch (IOException e) {
            throw new UserError("import-tracks: " + e.getMessage());
        }
        PrintWriter err = spec.commandLine().getErr();
        for (TrackImporter.Failure f : r.failed()) err.println("minigolf: not imported: " + f.source() + ": " + f.reason());
        err.flush();
        ObjectNode summary = Json.MAPPER.createObjectNode();
        summary.put("imported", r.imported().size());
        summary.put("failed", r.failed().size());
        summary.put("shapes", r.shapes());
        summary.put("out", target.toString());
        PrintWriter o = spec.commandLine().getOut();
        o.println(Json.MAPPER.writeValueAsString(summary));
        o.flush();
        return r.failed().isEmpty() ? 0 : 2;
    }
}
