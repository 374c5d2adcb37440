package minigolf.bot;

import minigolf.physics.World;

/** The robustness tests' hand-made courses, for tests in other packages. */
public final class BotRobustnessTestCourses {
    private BotRobustnessTestCourses() {
    }

    /** Flat, the hole inside a closed square of walls 2 m across. */
    public static World walledIn() {
        return BotRobustnessTest.course("walled in", "0", 0.1, 0.2, 5, 0.02135, BotRobustnessTest.BOX_ROUND_HOLE);
    }

    /**
     * The hole inside a box of 2 m walls: higher than any ball at the course's 5 m/s flies
     * (v^2/2g = 1.27 m), so neither a putt nor a chip holes.
     */
    public static World walledInHigh() {
        return BotRobustnessTest.course("walled in high", "0", 0.1, 0.2, 5, 0.02135,
                BotRobustnessTest.BOX_ROUND_HOLE.replace("\"height\":0.5", "\"height\":2"));
    }

    /** The same on slippery ground (mu_k 0.02): every shot rolls for seconds of simulated time. */
    public static World walledInSlippery() {
        return BotRobustnessTest.course("walled in, slippery", "0", 0.02, 0.05, 5, 0.02135, BotRobustnessTest.BOX_ROUND_HOLE);
    }
}
