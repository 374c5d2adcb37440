package minigolf.ui;

import java.io.IOException;
import java.io.InputStream;

/**
 * The interface's font: DejaVu Sans (src/main/resources/fonts/DejaVuSans.ttf, from Debian's
 * fonts-dejavu-core 2.37; Bitstream Vera licence with DejaVu's changes in the public domain, in
 * fonts/DejaVuSans-LICENSE.txt beside it), loaded from the classpath and baked by {@link FontAtlas}
 * at {@link #SIZE_PIXELS} times the interface scale (rasterised at its size: no scaling, no blur).
 */
public final class UiFont {
    public static final String RESOURCE = "/fonts/DejaVuSans.ttf";
    /** The size at scale 1 (a 900-pixel-high framebuffer or less), in pixels. */
    public static final float SIZE_PIXELS = 16f;
    /** The editor's size at scale 1: its panels hold many rows and must fit a 1366x768 screen. */
    public static final float EDITOR_SIZE_PIXELS = 14f;

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
}
