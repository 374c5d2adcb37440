package minigolf.game;

/**
 * One player's ball and count on the hole. {@code strokes} counts hits, {@code penalties} the
 * penalty strokes for water and out of bounds; the ball rests at (x, y).
 */
public record PlayerState(double x, double y, int strokes, int penalties, PlayerStatus status) {
    public PlayerState {
        if (!Double.isFinite(x) || !Double.isFinite(y)) throw new IllegalArgumentException("ball position must be finite");
        if (strokes < 0 || penalties < 0 || penalties > strokes) {
            throw new IllegalArgumentException("strokes " + strokes + " and penalties " + penalties + " do not fit");
        }
        if (status == null) throw new IllegalArgumentException("status must be given");
    }

    /** Hits plus penalty strokes. */
    public int total() {
        return strokes + penalties;
    }

    public boolean isPlaying() {
        return status == PlayerStatus.PLAYING;
    }
}
