package minigolf.game;

/**
 * A stroke that was rolling (or flying) when the game was saved: it is replayed from its start on
 * load, at the course clock it was played at (the game's clock, which stays there until it ends).
 */
public record PendingShot(double vx, double vy, double vz) {
    /** A putt. */
    public PendingShot(double vx, double vy) {
        this(vx, vy, 0);
    }
}
