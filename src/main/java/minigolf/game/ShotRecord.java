package minigolf.game;

import minigolf.physics.Outcome;

/**
 * One stroke as it was played: who, from where, how hard, and how it ended. After a penalty
 * ({@link Outcome#isPenalty()}) the ball went back to (startX, startY); {@code endX, endY} is
 * where it entered the water or left the bounds.
 */
public record ShotRecord(int player, double startX, double startY, double vx, double vy,
                         Outcome outcome, double endX, double endY) {
}
