package minigolf.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.bot.experiment.RunRecord;
import minigolf.classic.ClassicReport;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "classic-report",
        description = {"Prints the classic tracks' figures as Markdown: how many files import-tracks imported into",
                "IMPORTED and how many of its courses load, and, for each --results experiment (run with",
                "--suite IMPORTED/courses), each bot's games holed within 30 strokes, at or under the best human",
                "score, and its mean strokes against the human mean (docs/classic-tracks.md)."})
final class ClassicReportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "IMPORTED", description = "What import-tracks wrote (the folder with index.json).")
    Path imported;

    @Option(names = "--results", paramLabel = "DIR", description = "An experiment's folder (results.csv, or runs.csv while it runs); may be repeated (default: none: the import alone).")
    List<Path> results = new ArrayList<>();

    @Option(names = "--no-load", description = "Do not load every course (faster; the load figure then counts the index; default: off).")
    boolean noLoad;

    @Override
    public Integer call() {
        if (!Files.isRegularFile(imported.resolve("index.json"))) {
            throw new UserError(imported + ": no index.json (not a folder import-tracks wrote)");
        }
        try {
            ClassicReport.Import imp = ClassicReport.readImport(imported, !noLoad);
            List<RunRecord> runs = new ArrayList<>();
            for (Path r : results) {
                if (!Files.isDirectory(r)) throw new UserError("--results: " + r + ": no such folder");
                runs.addAll(ClassicReport.readRuns(r));
            }
            PrintWriter out = spec.commandLine().getOut();
            out.print(ClassicReport.markdown(imp, ClassicReport.figures(imp, runs)));
            out.flush();
        } catch (IOException e) {
            throw new UserError("classic-report: " + e.getMessage());
        }
        return 0;
    }
}
