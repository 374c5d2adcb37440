package minigolf.game;

import minigolf.physics.Outcome;

/**
 * One stroke as it was played: who, from where, how hard, at which moment of the course clock
 * (where moving obstacles make it matter: docs/course-format.md, "Moving obstacles"), and how it
 * ended. {@code vz} is 0 for a putt and positive for a chip (the ball leaves the ground). After a
 * penalty ({@link Outcome#isPenalty()}) the ball went back to (startX, startY); {@code endX, endY}
 * is where it entered the water or left the bounds.
 */
public record ShotRecord(int player, double startX, double startY, double vx, double vy, double vz,
                         Outcome outcome, double endX, double endY, double clock) {
    /** A stroke played at course clock 0 (on a course without moving obstacles the clock does not matter). */
    public ShotRecord(int player, double startX, double startY, double vx, double vy, double vz,
                      Outcome outcome, double endX, double endY) {
        this(player, startX, startY, vx, vy, vz, outcome, endX, endY, 0);
    }

    /** A putt (no vertical velocity), as every stroke was before chips. */
    public ShotRecord(int player, double startX, double startY, double vx, double vy, Outcome outcome, double endX,
                      double endY) {
        this(player, startX, startY, vx, vy, 0, outcome, endX, endY);
    }

    public boolean isChip() {
        return vz > 0;
    }
}
