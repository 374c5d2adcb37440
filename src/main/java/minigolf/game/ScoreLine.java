package minigolf.game;

/**
 * A player's line on the scorecard. {@code score} is hits plus penalties for a holed ball, and
 * the stroke limit plus one for a player who picked up.
 */
public record ScoreLine(String name, int strokes, int penalties, PlayerStatus status, int score, int rank) {
}
