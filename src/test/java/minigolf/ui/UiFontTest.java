package minigolf.ui;

import org.junit.jupiter.api.Test;

import java.io.InputStream;

import static org.junit.jupiter.api.Assertions.*;

/** The bundled font loads from the classpath and bakes into the atlas (CPU only: no GL needed to bake). */
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
    void itBakesAtTheScaledSize() {
        try (FontAtlas font = FontAtlas.bake(UiFont.SIZE_PIXELS * 1.5f)) {
            assertEquals(24f, font.height(), "16 px x 1.5");
            assertTrue(font.hasGlyph('g'));
            assertTrue(font.hasGlyph(0xB2), "superscript two (Latin-1)");
            assertFalse(font.hasGlyph(0x2713), "outside Latin-1: drawn as '?'");
            // The game's messages: "Holed in 3 — birdie!" showed "Holed in 3 ? birdie!" (Latin-1 only).
            assertTrue(font.hasGlyph(0x2014), "em dash");
            assertTrue(font.hasGlyph(0x2013) && font.hasGlyph(0x2019) && font.hasGlyph(0x2026), "en dash, quote, ellipsis");
            assertTrue(font.advance(0x2014) > font.advance('-'), "an em dash is its own glyph, wider than '-'");
            assertEquals(font.advance('?'), font.advance(0x2713));
            assertTrue(font.coveredPixels() > 5_000, "glyphs were rasterised: " + font.coveredPixels());
            // A proportional font: 'i' is narrower than 'W'.
            assertTrue(font.width("iiii") < font.width("WWWW") / 2);
            assertEquals(font.width("ab") + font.width("cd"), font.width("abcd"), 1e-3);
            assertTrue(font.width("Play") > 24 && font.width("Play") < 60, "about two ems: " + font.width("Play"));
        }
    }
}
