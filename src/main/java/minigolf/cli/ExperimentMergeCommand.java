package minigolf.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.bot.experiment.ExperimentException;
import minigolf.bot.experiment.Merge;
import minigolf.bot.experiment.Results;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "experiment-merge", description = {
        "Joins the shards of one experiment into results.csv, summary.md and the charts, as a single machine's run writes them.",
        "Checks that every shard has the same fingerprint (options, course files, program) and that no run is missing or duplicated."})
final class ExperimentMergeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "DIR",
            description = "Shard folders (shard-K-of-N), or the experiment's --out folder holding them.")
    List<Path> inputs;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Folder for the merged results (created).")
    Path out;

    @Override
    public Integer call() {
        Merge.Merged merged;
        try {
            merged = Merge.merge(inputs);
        } catch (ExperimentException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            throw new UserError("cannot read the shards: " + e.getMessage());
        }
        for (Path folder : merged.folders()) {
            if (sameFile(folder, out) || inputs.stream().anyMatch(input -> sameFile(input, out))) {
                throw new UserError("--out " + out + ": is one of the folders being merged; give another folder");
            }
        }
        try {
            String markdown = Results.write(out, merged.manifest(), merged.records());
            spec.commandLine().getErr().println("experiment-merge: " + merged.records().size() + " runs from "
                    + merged.folders().size() + " shard folder(s) -> " + out);
            spec.commandLine().getOut().println(markdown);
        } catch (IOException e) {
            throw new UserError(out + ": cannot write the results: " + e.getMessage());
        }
        return 0;
    }

    private static boolean sameFile(Path a, Path b) {
        try {
            return Files.exists(b) && Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }
}
