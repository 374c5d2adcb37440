package minigolf.game;

/** Where a player stands on the hole. */
public enum PlayerStatus {
    /** Still putting. */
    PLAYING("playing"),
    /** In the hole: skipped from now on. */
    HOLED("holed"),
    /** Reached the stroke limit without holing: picked up, skipped from now on. */
    PICKED_UP("picked-up");

    private final String jsonName;

    PlayerStatus(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }

    public static PlayerStatus fromJsonName(String name) {
        for (PlayerStatus s : values()) if (s.jsonName.equals(name)) return s;
        return null;
    }
}
