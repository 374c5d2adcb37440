package minigolf.course;

/** Which equations of motion the engine uses; see docs/course-format.md. */
public enum PhysicsModel {
    /** Crazy Putting's model: a = -g grad h - mu_k g v/|v|. */
    CLASSIC("classic"),
    /** The steep-slope form normalised by sqrt(1 + |grad h|^2). */
    COMPLETE("complete");

    private final String jsonName;

    PhysicsModel(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }

    /** The model with this course-file name, or null. */
    public static PhysicsModel fromJsonName(String name) {
        for (PhysicsModel m : values()) {
            if (m.jsonName.equals(name)) return m;
        }
        return null;
    }
}
