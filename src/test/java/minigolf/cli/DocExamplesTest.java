package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The README and the pages in docs/ cannot drift from the program: every {@code $ minigolf ...} example
 * in a code block is run and its output compared with the lines under it ("..." stands for any text),
 * and every option the command table of docs/cli.md names exists.
 */
class DocExamplesTest {

    private record Example(String command, List<String> expected) {
    }

    private static Path projectDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."));
    }

    /** README.md and every docs/*.md, one after the other. */
    private static String allPages() throws IOException {
        StringBuilder all = new StringBuilder(Files.readString(projectDir().resolve("README.md")));
        try (var pages = Files.list(projectDir().resolve("docs"))) {
            for (Path p : pages.filter(f -> f.toString().endsWith(".md")).sorted().toList()) {
                all.append("\n").append(Files.readString(p));
            }
        }
        return all.toString();
    }

    private static List<Example> examples(String pages) {
        List<Example> out = new ArrayList<>();
        boolean inBlock = false;
        Example current = null;
        for (String line : pages.split("\n")) {
            if (line.startsWith("```")) {
                inBlock = !inBlock;
                current = null;
                continue;
            }
            if (!inBlock) continue;
            if (line.startsWith("$ ")) {
                current = line.startsWith("$ minigolf ") ? new Example(line.substring(2), new ArrayList<>()) : null;
                if (current != null) out.add(current);
            } else if (current != null) {
                current.expected().add(line);
            }
        }
        return out;
    }

    /** "..." in the expected text matches any characters; everything else literally. */
    private static boolean matches(String expected, String actual) {
        String[] parts = expected.split(Pattern.quote("..."), -1);
        StringBuilder regex = new StringBuilder();
        for (int i = 0; i < parts.length; i++) {
            if (i > 0) regex.append(".*");
            regex.append(Pattern.quote(parts[i]));
        }
        return Pattern.compile(regex.toString(), Pattern.DOTALL).matcher(actual).matches();
    }

    @Test
    void everyExampleInTheDocsPrintsWhatTheDocsShow() throws IOException {
        List<Example> examples = examples(allPages());
        assertTrue(examples.stream().anyMatch(e -> e.command().startsWith("minigolf simulate courses/lake.json")),
                "the lake example is gone: " + examples);
        for (Example e : examples) {
            if (e.expected().isEmpty()) continue;
            String[] args = e.command().substring("minigolf ".length()).trim().split("\\s+");
            CliRun run = CliRun.of(args);
            String expected = String.join("\n", e.expected()).strip();
            assertTrue(matches(expected, run.out().strip()), "docs: $ " + e.command() + "\nshows:\n" + expected
                    + "\nbut it prints:\n" + run.out() + run.err());
        }
    }

    @Test
    void matchingTreatsDotsAsAnythingAndTheRestLiterally() {
        assertTrue(matches("{\"a\":1...}", "{\"a\":1.5}"));
        assertTrue(matches("x...y...z", "x12y34z"));
        assertFalse(matches("{\"outcome\":\"stopped\"...}", "{\"outcome\":\"water\",\"end\":[]}"));
        assertFalse(matches("a.b", "axb"), "a dot is a dot");
    }

    @Test
    void everyOptionInTheCommandTableExists() throws IOException {
        CommandLine root = new CommandLine(new MinigolfCommand());
        Pattern row = Pattern.compile("^\\| `minigolf ([a-z-]+)(.*?)` \\|", Pattern.MULTILINE);
        Matcher m = row.matcher(Files.readString(projectDir().resolve("docs/cli.md")));
        Set<String> seen = new TreeSet<>();
        List<String> problems = new ArrayList<>();
        while (m.find()) {
            String name = m.group(1);
            seen.add(name);
            CommandLine sub = root.getSubcommands().get(name);
            if (sub == null) {
                problems.add("no command " + name);
                continue;
            }
            Matcher option = Pattern.compile("--[a-z][a-z-]*").matcher(m.group(2));
            while (option.find()) {
                OptionSpec spec = sub.getCommandSpec().findOption(option.group());
                if (spec == null) problems.add(name + ": no option " + option.group());
            }
        }
        assertTrue(problems.isEmpty(), String.join("\n", problems));
        assertEquals(new TreeSet<>(root.getSubcommands().keySet()), seen, "the table lists every command once");
    }
}
