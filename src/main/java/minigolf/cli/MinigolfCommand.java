package minigolf.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import minigolf.app.GameLauncher;
import minigolf.course.CourseException;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.ScopeType;
import minigolf.render.NoOpenGlException;

/**
 * The {@code minigolf} command: without a subcommand it opens the game. {@code --help} and
 * {@code --version} are inherited by every subcommand ({@code minigolf simulate --help}).
 */
@Command(name = "minigolf", mixinStandardHelpOptions = true, versionProvider = VersionInfo.class,
        scope = ScopeType.INHERIT,
        description = "3D minigolf: play, simulate shots and benchmark the physics.",
        subcommands = {PlayCommand.class, SimulateCommand.class, BenchPhysicsCommand.class, BenchAccuracyCommand.class,
                RenderCommand.class,
                BenchRenderCommand.class, ParCheckCommand.class, SolveCommand.class, ExperimentCommand.class, ExperimentMergeCommand.class,
                EditCommand.class, BenchEditorCommand.class, BenchLimitsCommand.class, ServerCommand.class, BenchServerCommand.class,
                JoinCommand.class, ImportTracksCommand.class, ClassicReportCommand.class})
public final class MinigolfCommand implements Callable<Integer> {

    @Override
    public Integer call() {
        GameLauncher.playDefaultCourse();
        return 0;
    }

    /** Runs the command line and returns the exit code: 0 success, 2 bad input, 1 internal error. */
    public static int execute(String[] args, PrintWriter out, PrintWriter err) {
        CommandLine commandLine = new CommandLine(new MinigolfCommand());
        commandLine.setOut(out);
        commandLine.setErr(err);
        // Bad options: one line (picocli would add the whole usage text), exit code 2.
        commandLine.setParameterExceptionHandler((ex, arguments) -> {
            err.println("minigolf: " + firstLine(ex.getMessage()));
            err.flush();
            return 2;
        });
        commandLine.setExecutionExceptionHandler((exception, cmd, parseResult) -> {
            if (exception instanceof UserError || exception instanceof CourseException
                    || exception instanceof NoOpenGlException // a fact about the machine: one line, exit 2
                    || exception instanceof minigolf.physics.NonFiniteMotionException) { // about the course
                err.println("minigolf: " + exception.getMessage());
                err.flush();
                return 2;
            }
            if (exception instanceof minigolf.render.RenderException && noWindow(exception.getMessage())) {
                // No display, no OpenGL 3.3: the machine's condition, not a bug.
                err.println("minigolf: cannot open a window: " + firstLine(exception.getMessage()));
                err.flush();
                return 2;
            }
            err.println("minigolf: internal error: " + exception);
            if (System.getenv("MINIGOLF_DEBUG") != null) exception.printStackTrace(err);
            err.flush();
            return 1;
        });
        int code;
        try {
            code = commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            // Errors pass picocli's handler; they end as one line too, never a stack trace.
            err.println("minigolf: out of memory (the input asks for more than the Java heap holds;"
                    + " the file limits are in docs/course-format.md)");
            code = 2;
        } catch (StackOverflowError e) {
            err.println("minigolf: the input is nested too deeply (stack overflow)");
            code = 2;
        } catch (Error e) {
            err.println("minigolf: internal error: " + firstLine(String.valueOf(e)));
            if (System.getenv("MINIGOLF_DEBUG") != null) e.printStackTrace(err);
            code = 1;
        }
        out.flush();
        err.flush();
        return code;
    }

    /** The window system's refusals (Window's messages): no display, no OpenGL 3.3 context. */
    private static boolean noWindow(String message) {
        return message != null && (message.startsWith("GLFW could not be initialised")
                || message.startsWith("Could not create a window"));
    }

    private static String firstLine(String s) {
        if (s == null) return "";
        int nl = s.indexOf('\n');
        return nl >= 0 ? s.substring(0, nl) : s;
    }
}
