package minigolf.classic;

/**
 * The human statistics a track file carries on its {@code I} line.
 *
 * @param plays       plays that were finished
 * @param strokes     strokes of all those plays together
 * @param bestStrokes the fewest strokes any player took
 * @param bestPlayers how many plays took that few
 */
public record TrackStats(long plays, long strokes, int bestStrokes, long bestPlayers) {
    /** Mean strokes a play, or NaN when nobody has played the track. */
    public double averageStrokes() {
        return plays == 0 ? Double.NaN : (double) strokes / plays;
    }
}
