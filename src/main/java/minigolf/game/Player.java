package minigolf.game;

/**
 * A seat in a hot-seat game. {@code bot} names the bot that plays for a {@link PlayerKind#BOT}
 * player (one of {@link BotCatalog#names()}); it is null for humans.
 */
public record Player(String name, PlayerKind kind, String bot) {
    public static final int MAX_NAME_LENGTH = 24;

    public Player {
        if (name == null || name.isBlank()) throw new IllegalArgumentException("a player needs a name");
        if (name.length() > MAX_NAME_LENGTH) {
            throw new IllegalArgumentException("player names have at most " + MAX_NAME_LENGTH + " characters, got "
                    + name.length());
        }
        if (kind == null) throw new IllegalArgumentException("player " + name + " needs a kind (human or bot)");
        if (kind == PlayerKind.HUMAN) bot = null;
        if (kind == PlayerKind.BOT && (bot == null || bot.isBlank())) {
            throw new IllegalArgumentException("bot player " + name + " needs a bot name");
        }
    }

    public static Player human(String name) {
        return new Player(name, PlayerKind.HUMAN, null);
    }

    public static Player bot(String name, String bot) {
        return new Player(name, PlayerKind.BOT, bot);
    }

    public boolean isBot() {
        return kind == PlayerKind.BOT;
    }
}
