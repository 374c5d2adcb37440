package minigolf.bot.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Gathers the rows of an experiment's shards: checks that every folder belongs to the same
 * experiment (the same fingerprint) and that every run appears exactly once, and returns the
 * results in run order, ready for {@link Results#write}.
 */
public final class Merge {
    private static final Pattern SHARD_FOLDER = Pattern.compile("shard-(\\d+)-of-(\\d+)");
    /** Missing runs listed by name in the error before it only counts them. */
    private static final int LISTED = 5;

    /** The merged experiment: its manifest (no shard), every run's result in run order, and the folders read. */
    public record Merged(Manifest manifest, List<RunRecord> records, List<Path> folders) {
    }

    private Merge() {
    }

    /**
     * @param inputs shard folders (each with experiment.json and runs.csv), or folders holding
     *               shard folders named shard-K-of-N (an experiment's --out)
     */
    public static Merged merge(List<Path> inputs) throws IOException {
        List<Path> folders = new ArrayList<>();
        for (Path input : inputs) folders.addAll(expand(input));
        Map<Path, Path> real = new HashMap<>();
        for (Path f : folders) {
            Path previous = real.put(f.toRealPath(), f);
            if (previous != null) throw new ExperimentException(f + ": this shard folder is given twice (also as " + previous + ")");
        }
        Manifest reference = null;
        Path referenceFolder = null;
        List<Manifest> manifests = new ArrayList<>();
        for (Path f : folders) {
            Manifest m = Manifest.read(f);
            if (reference == null) {
                reference = m;
                referenceFolder = f;
            } else if (!reference.fingerprint().equals(m.fingerprint())) {
                throw new ExperimentException(f + ": belongs to a different experiment than " + referenceFolder + ": "
                        + reference.differences(m));
            }
            manifests.add(m);
        }
        RunPlan plan = reference.plan();
        RunRecord[] records = new RunRecord[plan.size()];
        int[] from = new int[plan.size()];
        List<String> partial = new ArrayList<>();
        int[] found = new int[folders.size()];
        for (int i = 0; i < folders.size(); i++) {
            Path log = folders.get(i).resolve(RunLog.FILE_NAME);
            RunLog.Contents contents = RunLog.read(log, plan, manifests.get(i).shard());
            if (contents.partialBytes() > 0) partial.add(log.toString());
            for (RunLog.Row row : contents.rows()) {
                if (records[row.run()] != null) {
                    throw new ExperimentException("run " + row.run() + " (" + describe(plan.run(row.run())) + ") is in both "
                            + folders.get(from[row.run()]) + " and " + folders.get(i) + ": give each shard once");
                }
                records[row.run()] = row.record();
                from[row.run()] = i;
                found[i]++;
            }
        }
        int missing = (int) Arrays.stream(records).filter(r -> r == null).count();
        if (missing > 0) throw new ExperimentException(missingMessage(plan, records, missing, folders, manifests, found, partial));
        return new Merged(reference.forShard(null), List.of(records), List.copyOf(folders));
    }

    private static List<Path> expand(Path input) throws IOException {
        if (!Files.isDirectory(input)) throw new ExperimentException(input + ": no such folder");
        if (Files.exists(input.resolve(Manifest.FILE_NAME))) return List.of(input);
        List<Path> shards;
        try (Stream<Path> listing = Files.list(input)) {
            shards = listing.filter(p -> SHARD_FOLDER.matcher(p.getFileName().toString()).matches())
                    .filter(p -> Files.exists(p.resolve(Manifest.FILE_NAME)))
                    .sorted(Comparator.comparing((Path p) -> shardNumber(p, 2)).thenComparing(p -> shardNumber(p, 1)))
                    .toList();
        }
        if (shards.isEmpty()) {
            throw new ExperimentException(input + ": neither a shard folder (no " + Manifest.FILE_NAME
                    + ") nor a folder of shard folders (shard-K-of-N)");
        }
        return shards;
    }

    private static int shardNumber(Path folder, int group) {
        var m = SHARD_FOLDER.matcher(folder.getFileName().toString());
        if (!m.matches()) return 0;
        try {
            return Integer.parseInt(m.group(group));
        } catch (NumberFormatException e) {
            return Integer.MAX_VALUE;
        }
    }

    private static String missingMessage(RunPlan plan, RunRecord[] records, int missing, List<Path> folders,
                                         List<Manifest> manifests, int[] found, List<String> partial) {
        StringBuilder m = new StringBuilder(missing + " of " + plan.size() + " runs are missing");
        List<String> notes = new ArrayList<>();
        Map<Integer, boolean[]> givenByCount = new HashMap<>();
        for (int i = 0; i < folders.size(); i++) {
            Shard s = manifests.get(i).shard();
            if (s == null) continue;
            givenByCount.computeIfAbsent(s.count(), n -> new boolean[n])[s.index()] = true;
            int expected = s.size(plan.size());
            if (found[i] < expected) notes.add("shard " + s + " (" + folders.get(i) + ") has " + found[i] + " of " + expected + " runs");
        }
        for (Map.Entry<Integer, boolean[]> e : givenByCount.entrySet()) {
            List<String> absent = new ArrayList<>();
            for (int k = 0; k < e.getKey(); k++) if (!e.getValue()[k]) absent.add(k + "/" + e.getKey());
            if (!absent.isEmpty()) notes.add("shard(s) " + String.join(", ", absent) + " not given");
        }
        if (!partial.isEmpty()) notes.add("cut off by a kill: " + String.join(", ", partial));
        if (!notes.isEmpty()) m.append(": ").append(String.join("; ", notes));
        List<String> listed = new ArrayList<>();
        for (int r = 0; r < records.length && listed.size() < LISTED; r++) {
            if (records[r] == null) listed.add("run " + r + " (" + describe(plan.run(r)) + ")");
        }
        m.append("; first missing: ").append(String.join(", ", listed));
        m.append(". Re-run the incomplete shards with the same command (they resume), then merge again");
        return m.toString();
    }

    private static String describe(RunPlan.Run run) {
        String noise = run.noise().isNone() ? "" : ", noise " + run.noise().position() + " m / " + run.noise().velocity() + " m/s";
        return run.course() + ", " + run.bot() + ", seed " + run.seed() + noise;
    }
}
