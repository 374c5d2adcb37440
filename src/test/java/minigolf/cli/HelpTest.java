package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;

/** Every command explains itself: --help (exit 0) lists every option with a description and its real default. */
class HelpTest {

    private static Collection<String> subcommands() {
        return new CommandLine(new MinigolfCommand()).getSubcommands().keySet();
    }

    @Test
    void thereAreSubcommandsToWalk() {
        assertTrue(subcommands().containsAll(List.of("play", "simulate", "render", "bench-render", "solve",
                "experiment", "edit", "bench-editor", "bench-physics", "bench-accuracy")), subcommands().toString());
    }

    @Test
    void topLevelHelpListsEveryCommand() {
        CliRun run = CliRun.of("--help");
        assertEquals(0, run.code(), run.err());
        assertEquals("", run.err());
        for (String name : subcommands()) assertTrue(run.out().contains("  " + name + " "), name + " missing:\n" + run.out());
    }

    @Test
    void everySubcommandAnswersHelpWithExitZeroAndDescribesEveryOption() {
        CommandLine root = new CommandLine(new MinigolfCommand());
        List<String> problems = new ArrayList<>();
        for (var entry : root.getSubcommands().entrySet()) {
            String name = entry.getKey();
            for (String flag : List.of("--help", "-h")) {
                CliRun run = CliRun.of(name, flag);
                assertEquals(0, run.code(), name + " " + flag + ": " + run.err());
                assertEquals("", run.err(), name + " " + flag);
                assertTrue(run.out().startsWith("Usage: minigolf " + name), run.out());
            }
            String help = CliRun.of(name, "--help").out();
            for (ArgSpec arg : entry.getValue().getCommandSpec().args()) {
                String label = arg instanceof OptionSpec o ? o.longestName() : arg.paramLabel();
                String description = String.join(" ", arg.description());
                if (description.isBlank()) {
                    problems.add(name + " " + label + ": no description");
                    continue;
                }
                if (arg instanceof OptionSpec o && o.usageHelp() || arg instanceof OptionSpec v && v.versionHelp()) continue;
                if (!help.contains(label)) problems.add(name + " " + label + ": not in --help");
                Object initial = arg.initialValue();
                if (arg.required() || arg instanceof CommandLine.Model.PositionalParamSpec) continue;
                // An option with a value must say its default; a flag must say it is off by default.
                if (!description.contains("default")) problems.add(name + " " + label + ": no default stated");
                if (initial != null && !(initial instanceof Boolean) && !(initial instanceof Collection)) {
                    // The default is rendered from the field (${DEFAULT-VALUE}), so it cannot drift from the code.
                    if (!rawDescription(arg).contains("${DEFAULT-VALUE}")) {
                        problems.add(name + " " + label + ": default " + initial + " written by hand, not ${DEFAULT-VALUE}");
                    } else if (!help.contains(String.valueOf(initial))) {
                        problems.add(name + " " + label + ": default " + initial + " not in --help");
                    }
                }
            }
        }
        assertTrue(problems.isEmpty(), String.join("\n", problems));
    }

    /** The description as written in the annotation (picocli's description() has its variables filled in). */
    private static String rawDescription(ArgSpec arg) {
        if (arg.userObject() instanceof java.lang.reflect.Field field) {
            CommandLine.Option option = field.getAnnotation(CommandLine.Option.class);
            if (option != null) return String.join(" ", option.description());
        }
        throw new AssertionError("not an annotated field: " + arg);
    }

    @Test
    void versionNamesTheBuildsVersionAndTheJava() {
        CliRun run = CliRun.of("--version");
        assertEquals(0, run.code(), run.err());
        String[] lines = run.out().split("\n");
        assertEquals("minigolf " + VersionInfo.version(), lines[0]);
        assertFalse(VersionInfo.version().equals("unknown"), "the build's version.properties is not on the classpath");
        assertTrue(lines[1].startsWith("Java " + System.getProperty("java.version")), lines[1]);
        assertEquals(run.out(), CliRun.of("simulate", "--version").out(), "subcommands inherit --version");
    }

    @Test
    void unknownOptionIsStillAnErrorWithExitTwo() {
        CliRun run = CliRun.of("simulate", "courses/flat.json", "--velocity", "1,0", "--helpme");
        assertEquals(2, run.code());
        assertEquals("minigolf: Unknown option: '--helpme'", run.err().strip(), "one line");
    }
}
