package minigolf.game;

/** Who takes a player's shots: a person at the keyboard or a bot on a worker thread. */
public enum PlayerKind {
    HUMAN("human"),
    BOT("bot");

    private final String jsonName;

    PlayerKind(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }

    public static PlayerKind fromJsonName(String name) {
        for (PlayerKind k : values()) if (k.jsonName.equals(name)) return k;
        return null;
    }
}
