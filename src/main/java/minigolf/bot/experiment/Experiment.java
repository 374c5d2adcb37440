package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.Bots;
import minigolf.bot.CancellationToken;
import minigolf.bot.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Every bot on every course with every seed, one run per task on a pool of threads (one per
 * core). Each run gets a fresh bot; worlds are immutable and shared. Results come back in a fixed
 * order (course, bot, seed) whatever order the threads finish in.
 */
public final class Experiment {
    /** A course of the suite: its file name (without .json) and its world. */
    public record SuiteCourse(String name, World world) {
    }

    private final List<SuiteCourse> courses;
    private final List<String> bots;
    private final int seeds;
    private final long budget;
    private final int maxStrokes;
    private final int threads;

    public Experiment(List<SuiteCourse> courses, List<String> bots, int seeds, long budget, int maxStrokes, int threads) {
        this.courses = List.copyOf(courses);
        this.bots = List.copyOf(bots);
        this.seeds = seeds;
        this.budget = budget;
        this.maxStrokes = maxStrokes;
        this.threads = threads;
    }

    public int runCount() {
        return courses.size() * bots.size() * seeds;
    }

    /** Runs everything; {@code finished} is called (from worker threads) with the count done so far. */
    public List<RunRecord> run(IntConsumer finished) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        AtomicInteger done = new AtomicInteger();
        List<Future<RunRecord>> futures = new ArrayList<>();
        try {
            for (SuiteCourse course : courses) {
                for (String botName : bots) {
                    for (int s = 1; s <= seeds; s++) {
                        long seed = s;
                        futures.add(pool.submit(() -> {
                            RunRecord r = runOne(course, botName, seed);
                            finished.accept(done.incrementAndGet());
                            return r;
                        }));
                    }
                }
            }
            List<RunRecord> records = new ArrayList<>();
            for (Future<RunRecord> f : futures) {
                try {
                    records.add(f.get());
                } catch (ExecutionException e) {
                    throw new IllegalStateException("a bot run failed: " + e.getCause(), e.getCause());
                }
            }
            return records;
        } finally {
            pool.shutdownNow();
        }
    }

    private RunRecord runOne(SuiteCourse course, String botName, long seed) {
        Bot bot = Bots.create(botName);
        if (bot == null) throw new IllegalArgumentException("unknown bot " + botName);
        Playthrough.Result result = Playthrough.play(bot, course.world(), SimulationSettings.DEFAULT, maxStrokes,
                budget, seed, CancellationToken.none(), BotProgress.NONE);
        boolean holeInOne = result.holed() && result.shots().size() == 1
                && result.shots().get(0).result().outcome() == Outcome.HOLED;
        return new RunRecord(course.name(), botName, seed, result.holed(), result.strokes(), holeInOne,
                result.simulations(), result.wallNanos() / 1e6);
    }
}
