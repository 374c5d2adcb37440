package minigolf.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.course.CourseException;
import minigolf.editor.CourseEditor;
import minigolf.editor.ui.EditorApp;
import minigolf.game.SettingsStore;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "edit", description = {"Opens the course editor on a course file, or on a new flat course.",
        "With --frames N it runs N frames (after the --keys, one per frame) and exits;"
                + " --screenshot saves what the window shows at the last frame."})
final class EditCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--screenshot", paramLabel = "FILE.png", description = "Saves the last frame as PNG (needs --frames; default: none).")
    Path screenshot;

    @Option(names = "--frames", paramLabel = "N", description = "Runs the editor N frames, then exits (default: ${DEFAULT-VALUE}, until the window is closed).")
    int frames;

    @Option(names = "--keys", paramLabel = "KEY", split = ",",
            description = "Key presses played one per frame through the keyboard path, e.g. D,D,ENTER,SHIFT,M,ENTER,CTRL+S (default: none).")
    List<String> keys;

    @Option(names = "--name", paramLabel = "NAME", description = "New course: its name (default: ${DEFAULT-VALUE}).")
    String name = "New course";

    @Option(names = "--size", paramLabel = "WxD", description = "New course: width x depth in metres (default: ${DEFAULT-VALUE}).")
    String size = "10x6";

    @Option(names = "--spacing", paramLabel = "M", description = "New course: grid spacing in metres (default: ${DEFAULT-VALUE}).")
    double spacing = 0.05;

    @Option(names = "--height", paramLabel = "EXPR", description = "New course: sample the height h(x, y) in metres instead of flat ground (default: flat, h = 0).")
    String height;

    @Override
    public Integer call() {
        if (frames < 0) throw new UserError("--frames: must be >= 0, got " + frames);
        if (screenshot != null && frames == 0) throw new UserError("--screenshot needs --frames N (N >= 1)");
        List<int[]> script = new ArrayList<>();
        if (keys != null) {
            for (String k : keys) {
                try {
                    script.add(EditorApp.parseKey(k));
                } catch (IllegalArgumentException e) {
                    throw new UserError("--keys: " + e.getMessage());
                }
            }
        }
        if (!script.isEmpty() && frames == 0) throw new UserError("--keys needs --frames N");
        CourseEditor editor;
        try {
            if (course != null) {
                if (!Files.exists(course)) throw new UserError(course + ": no such file");
                editor = CourseEditor.open(course);
            } else {
                String[] wd = size.toLowerCase(java.util.Locale.ROOT).split("x");
                if (wd.length != 2) throw new UserError("--size: expected WIDTHxDEPTH such as 10x6, got '" + size + "'");
                editor = CourseEditor.create(name, Double.parseDouble(wd[0]), Double.parseDouble(wd[1]), spacing, height);
            }
        } catch (CourseException e) {
            throw new UserError(e.getMessage());
        } catch (NumberFormatException e) {
            throw new UserError("--size: expected WIDTHxDEPTH such as 10x6, got '" + size + "'");
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        Path recoveryDir = SettingsStore.forUser().directory();
        new EditorApp(editor, new EditorApp.Options(screenshot, frames, script, recoveryDir, true)).run();
        return 0;
    }
}
