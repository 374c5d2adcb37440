package minigolf.online.store;

/**
 * One player's finished hole or round, for the leaderboard of {@code board} (a course's or a
 * round's name). {@code level} is the bot level for a bot (null for a person).
 */
public record Score(String board, String name, String level, int strokes, int par, String room, int seat,
                    long finishedMs) {
}
