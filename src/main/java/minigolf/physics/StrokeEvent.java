package minigolf.physics;

/**
 * Something that happened during a stroke, at time t, with the ball's contact point (its lowest
 * point) at (x, y, z). For impacts ({@code bounce}, {@code land}, {@code collision}) the ball's speed
 * just before and just after is given; elsewhere both are NaN.
 */
public record StrokeEvent(double t, Type type, double x, double y, double z, double speedBefore, double speedAfter) {
    public enum Type {
        /** The ball leaves the ground (a chip, a ramp, a drop, a bounce off an obstacle upwards). */
        LAUNCH("launch"),
        /** A flying ball touches the ground and rolls from there on. */
        LAND("land"),
        /** A flying ball touches the ground and flies on. */
        BOUNCE("bounce"),
        /** The ball hits an obstacle. */
        COLLISION("collision"),
        /** The ball enters a teleport's entry and leaves by an exit (the event's point: the exit). */
        TELEPORT("teleport"),
        WATER("water"),
        OUT("out"),
        HOLED("holed"),
        STOP("stop");

        private final String jsonName;

        Type(String jsonName) {
            this.jsonName = jsonName;
        }

        public String jsonName() {
            return jsonName;
        }
    }
}
