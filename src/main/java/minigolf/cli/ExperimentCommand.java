package minigolf.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import minigolf.bot.experiment.Experiment;
import minigolf.bot.experiment.ExperimentException;
import minigolf.bot.experiment.Manifest;
import minigolf.bot.experiment.Merge;
import minigolf.bot.experiment.Progress;
import minigolf.bot.experiment.Results;
import minigolf.bot.experiment.RunLog;
import minigolf.bot.experiment.RunPlan;
import minigolf.bot.experiment.RunRecord;
import minigolf.bot.play.Playthrough;
import minigolf.bot.experiment.Shard;
import minigolf.bot.play.Bots;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

@Command(name = "experiment", description = {
        "Runs bots on every course of a suite and writes results.csv, summary.md and charts.",
        "Rows are appended to DIR/runs.csv as runs end; the same command again resumes where it stopped.",
        "With --shard K/N (or a Slurm array task, or a Kubernetes Indexed Job with --shards N) it runs every",
        "N-th run from K into DIR/shard-K-of-N/; minigolf experiment-merge DIR --out MERGED joins the shards."})
final class ExperimentCommand implements Callable<Integer> {
    private static final Pattern SHARD_FOLDER = Pattern.compile("shard-(\\d+)-of-(\\d+)");

    @Spec
    CommandSpec spec;

    @Option(names = "--suite", required = true, paramLabel = "DIR", description = "Folder of course files (*.json) and of course folders holding a course.json (as import-tracks writes under courses/).")
    Path suite;

    @Option(names = "--bots", paramLabel = "a,b,c|all", description = "Bots to compare (default: ${DEFAULT-VALUE}).")
    String botList = "all";

    @Option(names = "--seeds", paramLabel = "N", description = "Runs per course and bot, seeds 1..N (default: ${DEFAULT-VALUE}).")
    int seeds = 5;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Folder for the results (created).")
    Path out;

    @Option(names = "--budget", paramLabel = "N", description = "Most simulations per game (default: ${DEFAULT-VALUE}).")
    long budget = 20_000;

    @Option(names = "--max-strokes", paramLabel = "K", description = "Most shots per game (default: ${DEFAULT-VALUE}).")
    int maxStrokes = 10;

    @Option(names = "--threads", paramLabel = "T",
            description = "Worker threads (default: SLURM_CPUS_PER_TASK when set, else one per core).")
    Integer threads;

    @Option(names = "--sweep-threads", paramLabel = "N",
            description = "Threads each game's bot spreads its sweeps over, besides --threads (default: ${DEFAULT-VALUE}); "
                    + "the same games for any N.")
    int sweepThreads = 1;

    @Option(names = "--shard", paramLabel = "K/N",
            description = "Run only every N-th run starting at K (K from 0) into DIR/shard-K-of-N/ "
                    + "(default: the Slurm array task or Kubernetes index when set, else every run).")
    String shardText;

    @Option(names = "--shards", paramLabel = "N",
            description = "The number of shards when the index comes from the scheduler (Kubernetes' JOB_COMPLETION_INDEX; "
                    + "default: none, required there).")
    Integer shards;

    @Option(names = "--time-limit", paramLabel = "SECONDS",
            description = "Wall time per game in seconds (default: ${DEFAULT-VALUE}): the bot then plays its best shot so far and the game stops.")
    double timeLimit = BotArguments.DEFAULT_TIME_LIMIT;

    @Option(names = "--noise-position", paramLabel = "S,S,...",
            description = "Standard deviations in metres of each stroke's start, per axis; a list makes a grid with "
                    + "--noise-velocity (default: ${DEFAULT-VALUE}).")
    String noisePositions = "0";

    @Option(names = "--noise-velocity", paramLabel = "S,S,...",
            description = "Standard deviations in m/s of the velocity played, per component (default: ${DEFAULT-VALUE}).")
    String noiseVelocities = "0";

    @Option(names = "--hide-friction",
            description = "Bots see every friction value as a prior and learn the truth from their strokes (default: ${DEFAULT-VALUE}).")
    boolean hideFriction;

    @Override
    public Integer call() throws InterruptedException {
        try {
            return runExperiment();
        } catch (ExperimentException e) {
            throw new UserError(e.getMessage());
        }
    }

    private int runExperiment() throws InterruptedException {
        List<String> bots = parseBots(botList);
        if (seeds < 1) throw new UserError("--seeds: must be at least 1, got " + seeds);
        if (budget < 1) throw new UserError("--budget: must be at least 1, got " + budget);
        if (maxStrokes < 1) throw new UserError("--max-strokes: must be at least 1, got " + maxStrokes);
        BotArguments.timeLimit(timeLimit);
        BotArguments.threads("--sweep-threads", sweepThreads);
        List<Double> positions = NoiseArguments.list("--noise-position", noisePositions);
        List<Double> velocities = NoiseArguments.list("--noise-velocity", noiseVelocities);
        int workers = threads != null ? threads : defaultThreads();
        if (workers < 1) throw new UserError("--threads: must be at least 1, got " + workers);
        if (shards != null && shards < 1) throw new UserError("--shards: must be at least 1, got " + shards);
        Shard shard = shardText != null ? Shard.parse(shardText) : Shard.fromEnvironment(System.getenv(), shards);
        if (shardText != null && shards != null && shards != shard.count()) {
            throw new UserError("--shards " + shards + " disagrees with --shard " + shardText);
        }
        List<Experiment.SuiteCourse> courses = new ArrayList<>();
        List<Manifest.CourseFile> files = new ArrayList<>();
        loadSuite(suite, courses, files);
        Manifest manifest = Manifest.of(spec.root().version()[0],
                new Manifest.Options(bots, seeds, budget, maxStrokes, positions, velocities, hideFriction), files)
                .forShard(shard);
        Experiment experiment = new Experiment(courses, bots, seeds, budget, maxStrokes, workers, timeLimit,
                RunPlan.grid(positions, velocities), hideFriction).spreadSweepsOver(sweepThreads);
        Path folder = shard == null ? out : out.resolve(shard.folderName());
        PrintWriter err = spec.commandLine().getErr();
        refuseMixedFolders(shard);
        try {
            Files.createDirectories(folder);
            Manifest existing = Manifest.read(folder);
            if (existing == null) {
                manifest.write(folder);
            } else if (!existing.fingerprint().equals(manifest.fingerprint())) {
                throw new UserError(folder + ": holds runs of a different experiment (" + manifest.differences(existing)
                        + "); give another --out, or delete the folder to start again");
            }
            RunPlan plan = experiment.plan();
            Path logFile = folder.resolve(RunLog.FILE_NAME);
            RunLog.Contents contents = RunLog.read(logFile, plan, shard);
            BitSet done = contents.done();
            int[] pending = IntStream.range(0, plan.size())
                    .filter(i -> (shard == null || shard.contains(i)) && !done.get(i)).toArray();
            int total = shard == null ? plan.size() : shard.size(plan.size());
            err.println("experiment: " + (shard == null ? "" : "shard " + shard + ", ") + total + " runs, "
                    + contents.rows().size() + " done before" + (contents.partialBytes() > 0 ? " (a cut-off last row redone)" : "")
                    + ", " + pending.length + " to run on " + workers + " thread(s); rows in " + logFile);
            err.flush();
            try (RunLog log = RunLog.openForAppend(logFile, contents);
                 ShotLog shots = new ShotLog(folder.resolve(ShotLog.FILE_NAME));
                 Progress progress = new Progress(err, Progress.onTerminal(), total, contents.rows().size(), 60)) {
                experiment.run(pending, new Experiment.Sink() {
                    @Override
                    public void played(int run, RunPlan.Run description, Playthrough.Result result) throws IOException {
                        shots.append(run, description, result);
                    }

                    @Override
                    public void finished(int run, RunRecord record) {
                        try {
                            log.append(run, record);
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                        progress.finished();
                    }
                });
            }
            if (shard != null) {
                spec.commandLine().getOut().println("shard " + shard + " complete: " + total + " runs in " + logFile
                        + "; when every shard is complete: minigolf experiment-merge " + out + " --out MERGED");
                return 0;
            }
            Merge.Merged merged = Merge.merge(List.of(folder));
            String markdown = Results.write(out, merged.manifest(), merged.records());
            spec.commandLine().getOut().println(markdown);
            return 0;
        } catch (IOException | UncheckedIOException e) {
            throw new UserError(folder + ": cannot write the results: " + e.getMessage());
        }
    }

    /**
     * One --out folder holds one kind of result: a whole experiment, or the shards of one split.
     * Anything else is almost always a mistake, such as re-submitting one Slurm array task on its
     * own (it would see an array of one task and run the whole experiment as shard 0/1), and would
     * leave the merge a folder it cannot read unambiguously.
     */
    private void refuseMixedFolders(Shard shard) {
        if (!Files.isDirectory(out)) return;
        if (shard != null && Files.exists(out.resolve(Manifest.FILE_NAME))) {
            throw new UserError(out + " holds an experiment run without shards (" + Manifest.FILE_NAME
                    + "); give the shards another --out");
        }
        try (Stream<Path> listing = Files.list(out)) {
            for (Path p : (Iterable<Path>) listing.sorted()::iterator) {
                Matcher m = SHARD_FOLDER.matcher(p.getFileName().toString());
                if (!m.matches()) continue;
                if (shard == null) {
                    throw new UserError(out + " holds shards (" + p.getFileName() + "); a run without --shard needs "
                            + "another --out (or merge them: minigolf experiment-merge " + out + " --out DIR)");
                }
                if (!m.group(2).equals(Integer.toString(shard.count()))) {
                    throw new UserError(out + " already holds shards of a " + m.group(2) + "-way split (" + p.getFileName()
                            + "), and this is shard " + shard + ". To re-run one task of that split give --shard K/"
                            + m.group(2) + " (with docs/cluster/experiment.sbatch: SHARDS=" + m.group(2)
                            + "); for a new split give another --out");
                }
            }
        } catch (IOException e) {
            throw new UserError(out + ": cannot list: " + e.getMessage());
        }
    }

    private static int defaultThreads() {
        String slurm = System.getenv("SLURM_CPUS_PER_TASK");
        if (slurm != null) {
            try {
                return Integer.parseInt(slurm.trim());
            } catch (NumberFormatException e) {
                throw new UserError("SLURM_CPUS_PER_TASK: not a whole number: '" + slurm + "'");
            }
        }
        return Runtime.getRuntime().availableProcessors();
    }

    static List<String> parseBots(String text) {
        if (text.trim().equals("all")) return Bots.names();
        List<String> names = new ArrayList<>();
        for (String part : text.split(",")) {
            String name = part.trim();
            if (name.isEmpty()) continue;
            if (Bots.create(name) == null) {
                throw new UserError("--bots: unknown bot '" + name + "'; known: " + String.join(", ", Bots.allNames()) + ", all");
            }
            if (!names.contains(name)) names.add(name);
        }
        if (names.isEmpty()) throw new UserError("--bots: no bot named");
        return names;
    }

    /** The course file of a course folder in a suite. */
    static final String FOLDER_COURSE = "course.json";

    /** Loads the suite's course files (sorted by name) and the SHA-256 of each file's bytes. */
    static void loadSuite(Path dir, List<Experiment.SuiteCourse> courses, List<Manifest.CourseFile> files) {
        if (!Files.isDirectory(dir)) throw new UserError("--suite: " + dir + ": no such folder");
        List<Path> paths;
        try (Stream<Path> listing = Files.list(dir)) {
            // Course files, and folders holding a course.json with its models (as import-tracks writes them).
            paths = listing.map(p -> Files.isDirectory(p) ? p.resolve(FOLDER_COURSE) : p)
                    .filter(p -> p.getFileName().toString().endsWith(".json") && Files.isRegularFile(p)).sorted().toList();
        } catch (IOException e) {
            throw new UserError("--suite: " + dir + ": cannot list: " + e.getMessage());
        }
        if (paths.isEmpty()) throw new UserError("--suite: " + dir + ": no course files (*.json)");
        for (Path f : paths) {
            String file = f.getFileName().toString();
            String name = file.equals(FOLDER_COURSE) && !f.getParent().equals(dir) ? f.getParent().getFileName().toString()
                    : file.substring(0, file.length() - 5);
            byte[] bytes;
            try {
                bytes = Files.readAllBytes(f);
            } catch (IOException e) {
                throw new UserError(f + ": cannot read: " + e.getMessage());
            }
            courses.add(new Experiment.SuiteCourse(name, CourseArgument.load(f)));
            files.add(new Manifest.CourseFile(name, Manifest.sha256(bytes)));
        }
    }
}
