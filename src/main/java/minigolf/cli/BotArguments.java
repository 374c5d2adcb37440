package minigolf.cli;

import minigolf.bot.Bot;
import minigolf.bot.CountingSimulator;
import minigolf.bot.play.Bots;

/** Bot names given on the command line. */
final class BotArguments {
    private BotArguments() {
    }

    /** The default of {@code --time-limit}: seconds of wall time for one game (every bot answers by then). */
    static final double DEFAULT_TIME_LIMIT = 60;

    /** Checks {@code --time-limit}: a positive, finite number of seconds. */
    static double timeLimit(double seconds) {
        if (!(seconds > 0) || !Double.isFinite(seconds) || seconds > 1e6) {
            throw new UserError("--time-limit: must be a number of seconds > 0 and at most 1000000, got " + seconds);
        }
        return seconds;
    }

    /** Checks a thread count for a bot's sweeps ({@code option} names it in the message): 1 to the most a simulator allows. */
    static int threads(String option, int threads) {
        if (threads < 1 || threads > CountingSimulator.MAX_THREADS) {
            throw new UserError(option + ": must be 1 to " + CountingSimulator.MAX_THREADS + ", got " + threads);
        }
        return threads;
    }

    static Bot bot(String name) {
        Bot bot = Bots.create(name);
        if (bot == null) {
            throw new UserError("--bot: unknown bot '" + name + "'; known: " + String.join(", ", Bots.allNames()));
        }
        return bot;
    }
}
