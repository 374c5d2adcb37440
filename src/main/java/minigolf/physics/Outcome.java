package minigolf.physics;

/** How a stroke ended. */
public enum Outcome {
    HOLED("holed"),
    STOPPED("stopped"),
    WATER("water"),
    OUT("out"),
    /**
     * The safety limit on simulated time was reached. It cannot happen where the continuous model
     * stops (the stop is exact); only a course without friction can roll for ever.
     */
    TIMEOUT("timeout");

    private final String jsonName;

    Outcome(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }

    /** Water and out of bounds cost a penalty stroke and put the ball back where the stroke began. */
    public boolean isPenalty() {
        return this == WATER || this == OUT;
    }
}
