package minigolf.ui;

/** Which screen the game shows. */
public enum Screen {
    MAIN_MENU, COURSES, NEW_GAME, SETTINGS, PLAYING, PAUSED, SCORECARD, TEST_BOT
}
