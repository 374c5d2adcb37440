package minigolf.ui;

import java.util.ArrayList;
import java.util.List;
import minigolf.render.Window;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.*;

/**
 * Text from other people's files (a course or round named with 100,000 characters, a long message)
 * reaches every kind of widget. Before {@link GuiText}, the binding encoded each label on LWJGL's
 * small native stack and the game died ("Out of stack space") as soon as such a name was drawn; now
 * every widget draws it cut short to the screen with "...".
 */
class LongTextTest {
    private static final int W = 640, H = 400;
    private static final String LONG = "Meadowbrook ".repeat(100_000 / 12 + 1).substring(0, 100_000);
    private static final String LONG_WORD = "x".repeat(100_000);

    private UiTestWindow ui;

    @BeforeEach
    void open() {
        ui = new UiTestWindow("long text test", W, H, 0f, 0f, 0f);
    }

    @AfterEach
    void close() {
        ui.close();
    }

    @Test
    void everyWidgetDrawsAHundredThousandCharacterNameCutToTheScreen() {
        List<float[]> widths = new ArrayList<>();
        GuiInt choice = new GuiInt(0);
        Runnable widgets = () -> {
            widths.clear();
            Gui.getBackgroundDrawList().addText(10, 10, 0xFFFFFFFF, LONG);
            Gui.setNextWindowPos(10, 10, GuiCond.Always);
            Gui.begin("Scorecard: " + LONG, GuiWindowFlags.NoCollapse);
            Gui.text(LONG);
            widths.add(Gui.lastItemRect());
            Gui.textColored(1, 0.8f, 0.3f, 1, LONG_WORD);
            widths.add(Gui.lastItemRect());
            Gui.textDisabled(LONG);
            Gui.textWrapped(LONG);
            Gui.textWrapped(LONG_WORD);
            widths.add(Gui.lastItemRect());
            Gui.button(LONG + "##play");
            widths.add(Gui.lastItemRect());
            Gui.selectable(LONG, false);
            Gui.checkbox(LONG, new GuiBool(false));
            widths.add(Gui.lastItemRect());
            Gui.radioButton(LONG, false);
            widths.add(Gui.lastItemRect());
            Gui.progressBar(0.5f, 200, 0, LONG);
            Gui.combo(LONG, choice, new String[]{LONG, "short"});
            if (Gui.beginMenu(LONG + "##menu")) {
                Gui.menuItem(LONG, LONG);
                Gui.endMenu();
            }
            if (Gui.beginTable("t", 2, 0)) {
                Gui.tableSetupColumn(LONG);
                Gui.tableSetupColumn("score");
                Gui.tableHeadersRow();
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.text(LONG);
                Gui.endTable();
            }
            Gui.end();
            Gui.begin(LONG + "##second", GuiWindowFlags.NoCollapse);
            Gui.text("a window named by a long id");
            Gui.end();
        };
        for (int i = 0; i < 3; i++) ui.frame(widgets); // the windows measure themselves, then draw
        for (float[] r : widths) {
            assertTrue(r[2] > 50 && r[2] <= W, "a widget as wide as the screen at most: " + java.util.Arrays.toString(r));
        }
        assertEquals(GL_NO_ERROR, glGetError());
    }

    @Test
    void aNameTagsPlateIsMeasuredOnTheTextAsDrawn() {
        // The tag's text is drawn cut to half the screen (GuiDrawList): its plate, which name tags
        // are laid out by, is that wide too, not 100,000 characters wide.
        float[][] plates = new float[2][];
        ui.frame(() -> {
            plates[0] = Gui.labelPlate(LONG);
            plates[1] = Gui.labelPlate("Ann");
        });
        float[] tag = plates[0], ann = plates[1];
        assertEquals(ann[1], tag[1], 1e-6, "one line high");
        float chrome = tag[1]; // 2 + twice the pad is less than the plate's height
        assertTrue(tag[0] <= W / 2f + chrome && tag[0] > W / 2f - 40, "the plate of the cut text: " + tag[0]);
        assertTrue(ann[0] > 10 && ann[0] < 80, "a short name's plate: " + ann[0]);
    }

    @Test
    void aLongTitleIsCutForTheWindowSystem() {
        ui.window.setTitle("Minigolf - " + LONG); // GLFW encodes it on the same small stack
        String shown = Window.shortTitle("Minigolf - " + LONG);
        assertEquals(200, shown.length());
        assertTrue(shown.startsWith("Minigolf - Meadowbrook") && shown.endsWith("..."), shown);
        assertEquals("Minigolf - Lake", Window.shortTitle("Minigolf - Lake"));
    }

    @Test
    void fitKeepsWhatFitsAndCutsTheRestWithDots() {
        FontAtlas font = FontAtlas.bake(16);
        try {
            assertEquals("Meadowbrook", GuiText.fit("Meadowbrook", font, 500));
            String cut = GuiText.fit(LONG, font, 300);
            assertTrue(cut.endsWith("..."), cut);
            assertTrue(font.width(cut) <= 300, "fits: " + font.width(cut));
            String longer = cut.substring(0, cut.length() - 3) + LONG.charAt(cut.length() - 3) + "...";
            assertTrue(font.width(longer) > 300, "the longest start that fits: one more character does not");
            assertTrue(LONG.startsWith(cut.substring(0, cut.length() - 3)));
            // Very wide screens still draw at most MAX_CHARS characters of one label.
            assertEquals(GuiText.MAX_CHARS + 3, GuiText.fit(LONG_WORD, font, 1e9f).length());
            // A surrogate pair is never split.
            String emoji = "\uD83D\uDE00".repeat(300);
            String e = GuiText.fit(emoji, font, 100);
            assertFalse(Character.isHighSurrogate(e.charAt(e.length() - 4)), "no lone high surrogate before the dots");
            assertEquals("...", GuiText.fit(LONG, font, 1));
            assertEquals("", GuiText.fit(null, font, 100));
            assertEquals("short", GuiText.id("short"));
            assertTrue(GuiText.id(LONG).length() <= GuiText.MAX_ID_CHARS);
            assertNotEquals(GuiText.id(LONG), GuiText.id(LONG + "!"), "different long ids stay apart");
        } finally {
            font.close();
        }
    }
}
