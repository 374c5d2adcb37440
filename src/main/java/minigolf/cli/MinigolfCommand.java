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
                BenchRenderCommand.class, SolveCommand.class, ExperimentCommand.class,
                EditCommand.class, BenchEditorCommand.class})
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
        commandLine.setExecutionExceptionHandler((exception, cmd, parseResult) -> {
            if (exception instanceof UserError || exception instanceof CourseException
                    || exception instanceof NoOpenGlException) { // a fact about the machine: one line, exit 2
                err.println("minigolf: " + exception.getMessage());
                err.flush();
                return 2;
            }
            err.println("minigolf: internal error: " + exception);
            if (System.getenv("MINIGOLF_DEBUG") != null) exception.printStackTrace(err);
            err.flush();
            return 1;
        });
        int code = commandLine.execute(args);
        out.flush();
        err.flush();
        return code;
    }
}
