package minigolf.physics;

import minigolf.course.CourseException;

/** Small courses with the elements of issue 24 (docs/course-format.md), from course JSON. */
final class ElementWorlds {
    private ElementWorlds() {
    }

    /**
     * A 10 m square course of height {@code height} (an expression), classic model, mu_k 0.1,
     * mu_s 0.3, maxSpeed 5, start (0, 0), the hole in a far corner, with {@code extra} top-level
     * fields (e.g. {@code "pushZones": [...]}).
     */
    static World course(String height, String extra) {
        String json = "{\"format\": 1, \"name\": \"test\", \"terrain\": {\"height\": \"" + height + "\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.3, \"maxSpeed\": 5},"
                + " \"start\": [0, 0], \"hole\": {\"position\": [4.5, 4.5], \"radius\": 0.1}"
                + (extra.isEmpty() ? "" : ", " + extra) + "}";
        try {
            return World.parse(json, "test.json");
        } catch (CourseException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    static World flat(String extra) {
        return course("0.1", extra);
    }

    static Simulator simulator(World world) {
        return new Simulator(world, SimulationSettings.DEFAULT);
    }
}
