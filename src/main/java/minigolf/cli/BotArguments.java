package minigolf.cli;

import minigolf.bot.Bot;
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

    static Bot bot(String name) {
        Bot bot = Bots.create(name);
        if (bot == null) {
            throw new UserError("--bot: unknown bot '" + name + "'; known: " + String.join(", ", Bots.allNames()));
        }
        return bot;
    }
}
