package minigolf.course;

/**
 * An area with its own friction (sand, a fast strip). Later zones in the file win over earlier ones.
 *
 * @param hazard null, or what happens to a ball in the zone: water that ends the stroke (docs/course-format.md)
 */
public record Zone(Shape shape, double kineticFriction, double staticFriction, Hazard hazard) {
    /** A zone without a hazard. */
    public Zone(Shape shape, double kineticFriction, double staticFriction) {
        this(shape, kineticFriction, staticFriction, null);
    }

    /**
     * Water or acid in a zone (the classic tracks' pools, drawn pixel by pixel where terrain water,
     * h &lt; 0, could only follow the heights): the stroke ends as in water when the ball enters the
     * zone ({@link When#ENTER}) or comes to rest in it ({@link When#REST}, shallow water it may roll
     * across). The ball then goes back to where the stroke began or to the course's start, with
     * {@code penalty} strokes (0 or 1) added.
     */
    public record Hazard(Kind kind, When when, ReturnTo returnTo, int penalty) {
        /** As terrain water: on entering, back to the stroke's start, one penalty stroke. */
        public static final Hazard WATER = new Hazard(Kind.WATER, When.ENTER, ReturnTo.STROKE_START, 1);

        public Hazard {
            if (penalty < 0 || penalty > 1) throw new IllegalArgumentException("penalty is 0 or 1");
        }

        /** What the zone looks like (the rules are the other fields). */
        public enum Kind implements Named { WATER, ACID }

        public enum When implements Named { ENTER, REST }

        public enum ReturnTo implements Named { STROKE_START, COURSE_START }

        /** An enum written in the course file by name: its constant's name in camel case ({@code strokeStart}). */
        public interface Named {
            String name();

            default String jsonName() {
                StringBuilder sb = new StringBuilder();
                boolean upper = false;
                for (char c : name().toCharArray()) {
                    if (c == '_') {
                        upper = true;
                    } else {
                        sb.append(upper ? c : Character.toLowerCase(c));
                        upper = false;
                    }
                }
                return sb.toString();
            }
        }
    }
}
