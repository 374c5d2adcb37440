package minigolf.ui;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.UserSettings;

/** What the screens ask the game to do; the window implements it on the render thread. */
public interface UiActions {
    void startGame(List<Player> players);

    /** Hits the current player's ball (the HIT button and the mouse drag both end here). */
    /** Hits the ball: vz = 0 is a putt, vz &gt; 0 a chip. */
    void hit(double vx, double vy, double vz);

    default void hit(double vx, double vy) {
        hit(vx, vy, 0);
    }

    void selectCourse(Path course);

    /** Reads the course and round folders again (the editor may have saved a course since). */
    default void refreshCourses() {
    }

    void testBot(String bot);

    void cancelBot();

    void saveGame();

    void loadGame(Path file);

    void applySettings(UserSettings settings);

    void toMainMenu();

    /** Opens the course editor (in its own window) on a new course. */
    void createCourse();

    void quit();

    /** Hides the {@link UiView#notice()}. */
    default void dismissNotice() {
    }

    /** Plays a round: the new-game dialog opens for it. */
    void chooseRound(minigolf.game.Round round);

    /** After a hole's card: on to the next hole (or the final card). */
    void nextHole();

    /** Plays the current hole's strokes again, exactly as played. */
    void watchReplay();

    /** Plays finished hole {@code hole} (0-based) of the round again, exactly as played (also after a load). */
    default void watchHole(int hole) {
    }

    void stopReplay();

    /** Sets and keeps the volumes. */
    void applyVolumes(minigolf.game.AudioSettings volumes);
}
