package minigolf.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.app.GameLauncher;
import minigolf.app.GameWindow;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "play", description = "Opens the game window on a course (default: the lake).")
final class PlayCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--screenshot", paramLabel = "FILE.png",
            description = "Renders one frame off-screen, saves it as PNG and exits.")
    Path screenshot;

    @Option(names = "--size", paramLabel = "WxH", description = "Screenshot size (default 1280x720).")
    String size = "1280x720";

    @Override
    public Integer call() {
        World world = course == null ? GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE) : CourseArgument.load(course);
        if (screenshot == null) {
            GameWindow.show(world.course(), world.terrain());
            return 0;
        }
        String[] parts = size.toLowerCase(java.util.Locale.ROOT).split("x");
        int width, height;
        try {
            width = Integer.parseInt(parts[0]);
            height = Integer.parseInt(parts[1]);
        } catch (RuntimeException e) {
            throw new UserError("--size: expected WxH such as 1280x720, got '" + size + "'");
        }
        if (parts.length != 2 || width < 16 || height < 16 || width > 8192 || height > 8192) {
            throw new UserError("--size: expected WxH between 16x16 and 8192x8192, got '" + size + "'");
        }
        GameWindow.screenshot(world.course(), world.terrain(), width, height, screenshot);
        return 0;
    }
}
