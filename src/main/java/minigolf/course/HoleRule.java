package minigolf.course;

/** When the ball counts as holed. */
public enum HoleRule {
    /** The ball comes to rest within the hole's radius (Crazy Putting). */
    REST("rest"),
    /** The ball drops when it passes close enough to the centre slowly enough (Penner). */
    CAPTURE("capture");

    private final String jsonName;

    HoleRule(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }

    public static HoleRule fromJsonName(String name) {
        for (HoleRule r : values()) {
            if (r.jsonName.equals(name)) return r;
        }
        return null;
    }
}
