package minigolf.ui;

import imgui.ImFont;
import imgui.ImGui;
import org.junit.jupiter.api.Test;

import java.io.InputStream;

import static org.junit.jupiter.api.Assertions.*;

/** The bundled font loads from the classpath into ImGui's atlas (CPU only: the atlas is rasterised without GL). */
class UiFontTest {
    @Test
    void theBundledFontAndItsLicenceAreOnTheClasspath() throws Exception {
        byte[] ttf = UiFont.bytes();
        assertTrue(ttf.length > 100_000, "a whole font: " + ttf.length);
        assertEquals(0x00010000, ((ttf[0] & 0xff) << 24) | ((ttf[1] & 0xff) << 16) | ((ttf[2] & 0xff) << 8) | (ttf[3] & 0xff),
                "TrueType's sfnt version");
        try (InputStream licence = UiFont.class.getResourceAsStream("/fonts/DejaVuSans-LICENSE.txt")) {
            assertNotNull(licence);
            assertTrue(new String(licence.readAllBytes()).contains("Bitstream Vera"));
        }
    }

    @Test
    void itIsTheAtlasDefaultFontAtTheScaledSize() {
        ImGui.createContext();
        try {
            ImFont font = UiFont.addTo(ImGui.getIO().getFonts(), UiFont.SIZE_PIXELS * 1.5f);
            assertTrue(ImGui.getIO().getFonts().build(), "the atlas builds");
            assertTrue(font.isLoaded());
            assertEquals(24f, font.getFontSize(), "16 px x 1.5");
            assertNotNull(font.findGlyphNoFallback('g'));
            assertNotNull(font.findGlyphNoFallback(0xB2), "superscript two (Latin-1)");
            // A proportional font: 'i' is narrower than 'W' (Dear ImGui's own font is monospaced).
            assertTrue(font.calcTextSizeAX(24f, Float.MAX_VALUE, 0f, "iiii") < font.calcTextSizeAX(24f, Float.MAX_VALUE, 0f, "WWWW") / 2);
        } finally {
            ImGui.destroyContext();
        }
    }
}
