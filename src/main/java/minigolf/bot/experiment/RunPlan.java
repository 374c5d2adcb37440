package minigolf.bot.experiment;

import java.util.List;
import minigolf.bot.NoiseModel;

/**
 * An experiment's runs in one fixed order: course by course (the suite's files sorted by name),
 * noise cell by noise cell (position noise outer, velocity noise inner, as the options list them),
 * bot by bot (as the options list them), seed 1..N. Without noise there is one cell (0, 0) and the
 * order is that of the plans before noise existed. Run i is computed from i and the options
 * alone, so every machine that shares the options agrees on what run i is, and a shard or a
 * resumed job can name a run by its index without listing the others.
 */
public record RunPlan(List<String> courses, List<String> bots, int seeds, List<NoiseModel> noises) {
    /** One unit of work: the only inputs of its result besides the experiment's options. */
    public record Run(int index, String course, String bot, long seed, NoiseModel noise) {
        public Run(int index, String course, String bot, long seed) {
            this(index, course, bot, seed, NoiseModel.NONE);
        }
    }

    /** A plan without noise. */
    public RunPlan(List<String> courses, List<String> bots, int seeds) {
        this(courses, bots, seeds, List.of(NoiseModel.NONE));
    }

    public RunPlan {
        courses = List.copyOf(courses);
        bots = List.copyOf(bots);
        noises = List.copyOf(noises);
        if (courses.isEmpty() || bots.isEmpty() || seeds < 1 || noises.isEmpty()) {
            throw new IllegalArgumentException("an experiment needs a course, a bot, a seed and a noise cell");
        }
        if ((long) courses.size() * noises.size() * bots.size() * seeds > Integer.MAX_VALUE) {
            throw new ExperimentException("too many runs: " + courses.size() + " courses x " + noises.size()
                    + " noise cells x " + bots.size() + " bots x " + seeds + " seeds is more than " + Integer.MAX_VALUE
                    + "; split the suite");
        }
    }

    /** The noise grid: every position noise with every velocity noise, position outer. */
    public static List<NoiseModel> grid(List<Double> positions, List<Double> velocities) {
        List<NoiseModel> cells = new java.util.ArrayList<>();
        for (double p : positions) for (double v : velocities) cells.add(new NoiseModel(p, v));
        return cells;
    }

    public int size() {
        return courses.size() * noises.size() * bots.size() * seeds;
    }

    public Run run(int index) {
        if (index < 0 || index >= size()) throw new IndexOutOfBoundsException("run " + index + " of " + size());
        int perCell = bots.size() * seeds;
        int perCourse = noises.size() * perCell;
        int withinCourse = index % perCourse;
        int withinCell = withinCourse % perCell;
        return new Run(index, courses.get(index / perCourse), bots.get(withinCell / seeds), withinCell % seeds + 1,
                noises.get(withinCourse / perCell));
    }

    /** Whether a results row belongs to run {@code index} (same course, bot, seed and noise). */
    public boolean matches(int index, RunRecord record) {
        Run run = run(index);
        return run.course().equals(record.course()) && run.bot().equals(record.bot()) && run.seed() == record.seed()
                && run.noise().position() == record.noisePosition() && run.noise().velocity() == record.noiseVelocity();
    }
}
