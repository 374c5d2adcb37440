package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.NoiseModel;
import minigolf.bot.play.Bots;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Every bot on every course with every seed, on a pool of threads. The runs are those of a
 * {@link RunPlan}; each gets a fresh bot and its own seed, and worlds are immutable and shared, so
 * a run's result depends only on the run, never on the thread, the machine or the order.
 */
public final class Experiment {
    /** A course of the suite: its file name (without .json) and its world. */
    public record SuiteCourse(String name, World world) {
    }

    /** Receives each finished run, from the worker threads. */
    public interface Sink {
        void finished(int run, RunRecord record) throws Exception;

        /** The run's strokes as played (called before {@link #finished}); by default ignored. */
        default void played(int run, RunPlan.Run description, Playthrough.Result result) throws Exception {
        }
    }

    private final Map<String, World> worlds = new HashMap<>();
    private final RunPlan plan;
    private final long budget;
    private final int maxStrokes;
    private final int threads;
    /** Wall-time limit per game in seconds (NaN: none). */
    private final double timeLimit;
    private final boolean hideFriction;
    /** Threads each game's bot spreads its sweeps over (the same games for any number). */
    private int sweepThreads = 1;

    public Experiment(List<SuiteCourse> courses, List<String> bots, int seeds, long budget, int maxStrokes, int threads) {
        this(courses, bots, seeds, budget, maxStrokes, threads, Double.NaN);
    }

    /** With a wall-time limit of {@code timeLimitSeconds} per game (NaN: none). */
    public Experiment(List<SuiteCourse> courses, List<String> bots, int seeds, long budget, int maxStrokes, int threads,
                      double timeLimitSeconds) {
        this(courses, bots, seeds, budget, maxStrokes, threads, timeLimitSeconds, List.of(NoiseModel.NONE), false);
    }

    /** Over a grid of noise cells (see {@link RunPlan}), friction hidden from the bots or not. */
    public Experiment(List<SuiteCourse> courses, List<String> bots, int seeds, long budget, int maxStrokes, int threads,
                      double timeLimitSeconds, List<NoiseModel> noises, boolean hideFriction) {
        for (SuiteCourse c : courses) worlds.put(c.name(), c.world());
        this.plan = new RunPlan(courses.stream().map(SuiteCourse::name).toList(), bots, seeds, noises);
        this.hideFriction = hideFriction;
        this.budget = budget;
        this.maxStrokes = maxStrokes;
        this.threads = threads;
        this.timeLimit = timeLimitSeconds;
    }

    /** Lets each game's bot spread its sweeps over {@code threads} threads (besides the runs' own threads). */
    public Experiment spreadSweepsOver(int threads) {
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        this.sweepThreads = threads;
        return this;
    }

    public RunPlan plan() {
        return plan;
    }

    public int runCount() {
        return plan.size();
    }

    /**
     * Runs the given runs of the plan, each handed to the sink as it ends. Threads take the next
     * run from a shared counter rather than from a queue of all of them, so millions of runs cost
     * no memory. The first failure (of a run or of the sink) stops the others and is thrown.
     */
    public void run(int[] runs, Sink sink) throws InterruptedException {
        AtomicInteger next = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        List<Thread> workers = new ArrayList<>();
        for (int t = 0; t < Math.min(threads, Math.max(1, runs.length)); t++) {
            Thread worker = new Thread(() -> {
                int i;
                while (failure.get() == null && (i = next.getAndIncrement()) < runs.length) {
                    try {
                        RunPlan.Run description = plan.run(runs[i]);
                        Playthrough.Result result = play(description);
                        sink.played(runs[i], description, result);
                        sink.finished(runs[i], record(description, result));
                    } catch (Throwable e) {
                        failure.compareAndSet(null, e);
                    }
                }
            }, "experiment-" + t);
            worker.setDaemon(true);
            workers.add(worker);
            worker.start();
        }
        try {
            for (Thread w : workers) w.join();
        } catch (InterruptedException e) {
            failure.compareAndSet(null, e);
            for (Thread w : workers) w.join();
            throw e;
        }
        Throwable e = failure.get();
        if (e instanceof RuntimeException r) throw r;
        if (e instanceof Error r) throw r;
        if (e != null) throw new IllegalStateException("a bot run failed: " + e, e);
    }

    /** One run, from its description alone. */
    public RunRecord runOne(RunPlan.Run run) {
        return record(run, play(run));
    }

    /** Plays one run's game. */
    private Playthrough.Result play(RunPlan.Run run) {
        Bot bot = Bots.create(run.bot());
        if (bot == null) throw new IllegalArgumentException("unknown bot " + run.bot());
        return Playthrough.play(bot, worlds.get(run.course()), SimulationSettings.DEFAULT, maxStrokes,
                budget, run.seed(), Double.isNaN(timeLimit) ? CancellationToken.none() : CancellationToken.withTimeLimit(timeLimit),
                BotProgress.NONE, new PlayConditions(run.noise(), hideFriction), sweepThreads);
    }

    private static RunRecord record(RunPlan.Run run, Playthrough.Result result) {
        boolean holeInOne = result.holed() && result.shots().size() == 1
                && result.shots().get(0).result().outcome() == Outcome.HOLED;
        return new RunRecord(run.course(), run.bot(), run.seed(), run.noise().position(), run.noise().velocity(),
                result.holed(), result.strokes(), holeInOne,
                result.simulations(), result.wallNanos() / 1e6);
    }
}
