package minigolf.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The screen host's calls, in libGDX's order: hide the old screen, show the new one, tell it the size. */
class ScreenHostTest {
    private final List<String> calls = new ArrayList<>();

    private Screen screen(String name) {
        return new Screen() {
            @Override
            public void show() {
                calls.add(name + ".show");
            }

            @Override
            public void hide() {
                calls.add(name + ".hide");
            }

            @Override
            public void resize(int width, int height) {
                calls.add(name + ".resize " + width + "x" + height);
            }

            @Override
            public void render(float width, float height) {
            }
        };
    }

    @Test
    void switchingHidesTheOldShowsTheNewAndTellsItTheSize() {
        Screen menu = screen("menu"), play = screen("play");
        ScreenHost host = new ScreenHost(menu);
        host.setScreen(play); // before the first frame: no size yet
        host.resize(1280, 720);
        host.resize(1280, 720); // unchanged: not told again
        host.setScreen(play); // already shown: nothing
        host.setScreen(menu);
        assertSame(menu, host.current());
        assertEquals(List.of("menu.hide", "play.show", "play.resize 1280x720", "play.hide", "menu.show",
                "menu.resize 1280x720"), calls);
    }
}
