package minigolf.course;

/**
 * An attracting (strength &gt; 0) or repelling (strength &lt; 0) point force on the rolling ball
 * (course file field {@code magnets}), as the classic game's magnets. Within {@code radius} of
 * {@code position} it pulls with (27/4) strength (1 - d/R)² d/R, d the distance: 0 at the centre
 * and at the rim, |strength| (m/s²) at its strongest, R/3 from the centre.
 */
public record Magnet(Vec2 position, double radius, double strength) {
    /** The force's profile f(u) = (27/4) u (1 - u)², u = d/R in [0, 1]: its largest value, 1, is at u = 1/3. */
    public static double profile(double u) {
        if (!(u < 1)) return 0;
        double rest = 1 - u;
        return 6.75 * u * rest * rest;
    }
}
