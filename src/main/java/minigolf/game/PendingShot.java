package minigolf.game;

/** A stroke that was rolling when the game was saved: it is replayed from its start on load. */
public record PendingShot(double vx, double vy) {
}
