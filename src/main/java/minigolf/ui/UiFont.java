package minigolf.ui;

import imgui.ImFont;
import imgui.ImFontAtlas;
import imgui.ImFontConfig;

import java.io.IOException;
import java.io.InputStream;

/**
 * The interface's font: DejaVu Sans (src/main/resources/fonts/DejaVuSans.ttf, from Debian's
 * fonts-dejavu-core 2.37; Bitstream Vera licence with DejaVu's changes in the public domain, in
 * fonts/DejaVuSans-LICENSE.txt beside it), loaded from the classpath into ImGui's font atlas at
 * {@link #SIZE_PIXELS} times the interface scale, instead of Dear ImGui's 13-pixel bitmap font
 * scaled up (blurry). Dear ImGui's default glyphs, Basic Latin and Latin-1 (the interface's
 * strings use no others; a glyph-range array would have to outlive the call, which the binding
 * does not promise).
 */
public final class UiFont {
    public static final String RESOURCE = "/fonts/DejaVuSans.ttf";
    /** The size at scale 1 (a 900-pixel-high framebuffer or less), in pixels. */
    public static final float SIZE_PIXELS = 16f;
    private UiFont() {
    }

    /** The font file's bytes. */
    public static byte[] bytes() {
        try (InputStream in = UiFont.class.getResourceAsStream(RESOURCE)) {
            if (in == null) throw new IllegalStateException("font " + RESOURCE + " is missing from the classpath");
            return in.readAllBytes();
        } catch (IOException e) {
            throw new IllegalStateException("font " + RESOURCE + " could not be read: " + e.getMessage(), e);
        }
    }

    /** The editor's size at scale 1: its panels hold many rows and must fit a 1366x768 screen. */
    public static final float EDITOR_SIZE_PIXELS = 14f;

    /** Adds the font to the atlas as its first (default) font at {@code pixels} (rounded); returns it. */
    public static ImFont addTo(ImFontAtlas atlas, float pixels) {
        ImFontConfig config = new ImFontConfig();
        try {
            config.setName("DejaVu Sans");
            config.setOversampleH(2);
            config.setOversampleV(1);
            return atlas.addFontFromMemoryTTF(bytes(), Math.round(pixels), config);
        } finally {
            config.destroy();
        }
    }
}
