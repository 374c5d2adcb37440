package minigolf.game;

import java.util.Locale;

/**
 * What the game says when a stroke comes to rest, in a player's words: "In the water: +1 stroke",
 * "Holed in 3 - birdie!", "2.4 m to the hole". No coordinates: a distance to the hole at most.
 */
public final class StrokeNews {
    private StrokeNews() {
    }

    /**
     * The message for {@code r}, played by {@code name} (named when {@code severalPlayers}), who now
     * stands at {@code after}; {@code par} is the hole's par, or null on a course without one.
     */
    public static String of(ShotRecord r, PlayerState after, String name, boolean severalPlayers, Integer par,
                            double holeX, double holeY) {
        String who = severalPlayers ? name + " " : "";
        String text = switch (r.outcome()) {
            case HOLED -> (severalPlayers ? who + "holed" : "Holed") + " in " + after.total() + " \u2014 " + scoreName(after.total(), par);
            case WATER -> (severalPlayers ? who + "is in" : "In") + " the water: +1 stroke";
            case OUT -> (severalPlayers ? who + "is out" : "Out") + " of bounds: +1 stroke";
            case STOPPED -> (severalPlayers ? name + ": " : "")
                    + String.format(Locale.ROOT, "%.1f m to the hole", Math.hypot(after.x() - holeX, after.y() - holeY));
            case TIMEOUT -> (severalPlayers ? name + ": still" : "Still") + " rolling after the time limit; the ball stays there";
        };
        if (after.status() == PlayerStatus.PICKED_UP) {
            text += " \u2014 the stroke limit: " + (severalPlayers ? name + " picks" : "picked") + " up";
        }
        return text;
    }

    /** "hole in one!", "birdie!", "par", "bogey", ... for {@code strokes} on a hole of {@code par} (null: no par). */
    public static String scoreName(int strokes, Integer par) {
        if (strokes == 1) return "hole in one!";
        if (par == null) return strokes + " strokes";
        int d = strokes - par;
        return switch (d) {
            case -3 -> "albatross!";
            case -2 -> "eagle!";
            case -1 -> "birdie!";
            case 0 -> "par";
            case 1 -> "bogey";
            case 2 -> "double bogey";
            case 3 -> "triple bogey";
            default -> d < 0 ? (-d) + " under par!" : d + " over par";
        };
    }
}
