package minigolf.cli;

import minigolf.bot.Bot;
import minigolf.bot.Bots;

/** Bot names given on the command line. */
final class BotArguments {
    private BotArguments() {
    }

    static Bot bot(String name) {
        Bot bot = Bots.create(name);
        if (bot == null) {
            throw new UserError("--bot: unknown bot '" + name + "'; known: " + String.join(", ", Bots.names()));
        }
        return bot;
    }
}
