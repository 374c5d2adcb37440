package minigolf.bot.experiment;

import java.util.List;

/**
 * An experiment's runs in one fixed order: course by course (the suite's files sorted by name),
 * bot by bot (as the options list them), seed 1..N. Run i is computed from i and the options
 * alone, so every machine that shares the options agrees on what run i is, and a shard or a
 * resumed job can name a run by its index without listing the others.
 */
public record RunPlan(List<String> courses, List<String> bots, int seeds) {
    /** One unit of work: the only inputs of its result besides the experiment's options. */
    public record Run(int index, String course, String bot, long seed) {
    }

    public RunPlan {
        courses = List.copyOf(courses);
        bots = List.copyOf(bots);
        if (courses.isEmpty() || bots.isEmpty() || seeds < 1) {
            throw new IllegalArgumentException("an experiment needs a course, a bot and a seed");
        }
        if ((long) courses.size() * bots.size() * seeds > Integer.MAX_VALUE) {
            throw new ExperimentException("too many runs: " + courses.size() + " courses x " + bots.size()
                    + " bots x " + seeds + " seeds is more than " + Integer.MAX_VALUE + "; split the suite");
        }
    }

    public int size() {
        return courses.size() * bots.size() * seeds;
    }

    public Run run(int index) {
        if (index < 0 || index >= size()) throw new IndexOutOfBoundsException("run " + index + " of " + size());
        int perCourse = bots.size() * seeds;
        int withinCourse = index % perCourse;
        return new Run(index, courses.get(index / perCourse), bots.get(withinCourse / seeds), withinCourse % seeds + 1);
    }

    /** Whether a results row belongs to run {@code index} (same course, bot and seed). */
    public boolean matches(int index, RunRecord record) {
        Run run = run(index);
        return run.course().equals(record.course()) && run.bot().equals(record.bot()) && run.seed() == record.seed();
    }
}
