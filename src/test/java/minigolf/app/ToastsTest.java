package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Messages said together (the last putt, the birdie, the round's high score) were joined into one
 * line that the screen cut short with "..." on the 18-hole final card; now each has its own line.
 */
class ToastsTest {
    private double now;
    private final Toasts toasts = new Toasts(() -> now);

    @Test
    void messagesSaidTogetherKeepOneLineEachTheLatestFour() {
        String[] said = {"Bot 2 (Medium): 0.4 m to the hole", "Bot 2 (Medium) holed in 2 \u2014 birdie!",
            "Bot (Hard) holed in 2 \u2014 birdie!", "Bot (Hard): first round 34, high score #1",
            "Bot 2 (Medium): first round 49, high score #2"};
        for (String s : said) {
            toasts.say(s);
            now += 0.1;
        }
        assertEquals(List.of(said[1], said[2], said[3], said[4]), toasts.messageLines());
    }

    @Test
    void aMessageSaidLaterReplacesTheOldOnesAndAllFadeAfterTheirSeconds() {
        toasts.say("Ann: 3.0 m to the hole");
        now = 0.2;
        toasts.say("Ann holed in 2 \u2014 birdie!");
        now = 1.0;
        toasts.say("Bob: 1.2 m to the hole");
        assertEquals(List.of("Bob: 1.2 m to the hole"), toasts.messageLines());
        now = 1.0 + Toasts.SECONDS - 0.01;
        assertEquals(1, toasts.messageLines().size());
        now = 1.0 + Toasts.SECONDS + 0.01;
        assertEquals(List.of(), toasts.messageLines());
    }
}
