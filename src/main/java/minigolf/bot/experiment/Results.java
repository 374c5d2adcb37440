package minigolf.bot.experiment;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.io.AtomicFile;

/**
 * A whole experiment's outputs: experiment.json, results.csv (rows in run order), summary.md and
 * the charts. A single machine's run and a merge of shards both end here, with the same rows in the
 * same order, so their files differ only in what the clocks measured.
 */
public final class Results {
    public static final String RESULTS_CSV = "results.csv";
    public static final String SUMMARY_MD = "summary.md";

    private Results() {
    }

    /**
     * @param records every run's result, in run order
     * @return the summary's markdown
     */
    public static String write(Path directory, Manifest manifest, List<RunRecord> records) throws IOException {
        if (records.size() != manifest.runs()) {
            throw new IllegalArgumentException(records.size() + " records for " + manifest.runs() + " runs");
        }
        Files.createDirectories(directory);
        manifest.forShard(null).write(directory);
        StringBuilder csv = new StringBuilder(RunRecord.CSV_HEADER).append('\n');
        for (RunRecord r : records) csv.append(r.csvRow()).append('\n');
        AtomicFile.write(directory.resolve(RESULTS_CSV), csv.toString().getBytes(StandardCharsets.UTF_8));
        List<Summary.Line> lines = Summary.lines(records);
        Manifest.Options o = manifest.options();
        String markdown = Summary.markdown(lines, o.seeds(), o.budget(), o.maxStrokes());
        AtomicFile.write(directory.resolve(SUMMARY_MD), markdown.getBytes(StandardCharsets.UTF_8));
        Charts.write(lines, directory);
        return markdown;
    }
}
