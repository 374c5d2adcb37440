package minigolf.ui;

/** Which screen the game shows. */
public enum Screen {
    MAIN_MENU, COURSES, NEW_GAME, SETTINGS, PLAYING, PAUSED, SCORECARD, TEST_BOT,
    /** A round's card: between holes (with "Next hole") and at the end (with the winner). */
    ROUND_CARD,
    HELP,
    /** The hole's strokes played again. */
    REPLAY
}
