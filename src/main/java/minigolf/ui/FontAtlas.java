package minigolf.ui;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.charset.StandardCharsets;
import org.lwjgl.nuklear.NkQueryFontGlyphCallback;
import org.lwjgl.nuklear.NkTextWidthCallback;
import org.lwjgl.nuklear.NkUserFont;
import org.lwjgl.nuklear.NkUserFontGlyph;
import org.lwjgl.stb.STBTTAlignedQuad;
import org.lwjgl.stb.STBTTFontinfo;
import org.lwjgl.stb.STBTTPackContext;
import org.lwjgl.stb.STBTTPackedchar;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.stb.STBTruetype.*;
import static org.lwjgl.system.MemoryUtil.*;

/**
 * The interface font ({@link UiFont}) baked with STB truetype into a coverage atlas: Basic Latin,
 * Latin-1 and the dashes, quotes, bullet and ellipsis of General Punctuation (U+2010 to U+2027: the
 * game's messages say "Holed in 3 — birdie!"); anything else is drawn as '?'. Baking needs no GL;
 * {@link #userFont()} uploads the atlas and hands Nuklear a font that measures and places glyphs
 * exactly as {@link #width(CharSequence)} does, so layout code can size widgets itself.
 * Owns native memory: close it.
 */
public final class FontAtlas implements AutoCloseable {
    static final int FIRST = 32, COUNT = 224;
    static final int PUNCTUATION_FIRST = 0x2010, PUNCTUATION_COUNT = 0x18;
    private static final int ATLAS = 1024;

    private final ByteBuffer ttf; // stb_truetype reads the font file while the atlas lives
    private final STBTTFontinfo info = STBTTFontinfo.malloc();
    private final STBTTPackedchar.Buffer chars = STBTTPackedchar.malloc(COUNT + PUNCTUATION_COUNT);
    private final float pixels, ascent;
    private ByteBuffer coverage; // until uploaded
    private int texture;
    private NkUserFont font;
    private NkTextWidthCallback widthCallback;
    private NkQueryFontGlyphCallback queryCallback;
    private boolean closed;

    private FontAtlas(float pixels) {
        this.pixels = Math.round(pixels);
        byte[] bytes = UiFont.bytes();
        ttf = memAlloc(bytes.length).put(bytes).flip();
        coverage = memCalloc(ATLAS * ATLAS);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            if (!stbtt_InitFont(info, ttf)) throw new IllegalStateException("the bundled font is not a TrueType font");
            float scale = stbtt_ScaleForPixelHeight(info, this.pixels);
            IntBuffer a = stack.mallocInt(1);
            stbtt_GetFontVMetrics(info, a, null, null);
            ascent = a.get(0) * scale;
            STBTTPackContext pc = STBTTPackContext.malloc(stack);
            if (!stbtt_PackBegin(pc, coverage, ATLAS, ATLAS, 0, 1, NULL)) throw new IllegalStateException("font atlas");
            stbtt_PackSetOversampling(pc, 2, 1); // sharper horizontal positions, as before
            boolean packed = stbtt_PackFontRange(pc, ttf, 0, this.pixels, FIRST, chars.slice(0, COUNT))
                    && stbtt_PackFontRange(pc, ttf, 0, this.pixels, PUNCTUATION_FIRST, chars.slice(COUNT, PUNCTUATION_COUNT));
            stbtt_PackEnd(pc);
            if (!packed) throw new IllegalStateException("the font does not fit its atlas at " + this.pixels + " px");
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /** Bakes the bundled font at {@code pixels} (rounded) per line. */
    public static FontAtlas bake(float pixels) {
        return new FontAtlas(pixels);
    }

    /** The line height in pixels. */
    public float height() {
        return pixels;
    }

    /** Whether the font has a real glyph for the code point (not the '?' stand-in). */
    public boolean hasGlyph(int codePoint) {
        return slot(codePoint) >= 0 && stbtt_FindGlyphIndex(info, codePoint) != 0;
    }

    /** Where the code point's glyph is in {@code chars}, or -1 if it was not baked. */
    private static int slot(int codePoint) {
        if (codePoint >= FIRST && codePoint < FIRST + COUNT) return codePoint - FIRST;
        if (codePoint >= PUNCTUATION_FIRST && codePoint < PUNCTUATION_FIRST + PUNCTUATION_COUNT) {
            return COUNT + codePoint - PUNCTUATION_FIRST;
        }
        return -1;
    }

    /** The glyph drawn for the code point: its own, or '?'. */
    private static int drawn(int codePoint) {
        int s = slot(codePoint);
        return s >= 0 ? s : '?' - FIRST;
    }

    /** The advance of one code point in pixels. */
    public float advance(int codePoint) {
        return chars.get(drawn(codePoint)).xadvance();
    }

    /** The width of a line of text in pixels, as Nuklear will draw it. */
    public float width(CharSequence text) {
        float w = 0;
        for (int i = 0; i < text.length(); ) {
            int cp = Character.codePointAt(text, i);
            w += advance(cp);
            i += Character.charCount(cp);
        }
        return w;
    }

    /** Number of atlas pixels with any coverage (for tests: the glyphs were rasterised). */
    int coveredPixels() {
        if (coverage == null) throw new IllegalStateException("already uploaded");
        int n = 0;
        for (int i = 0; i < coverage.capacity(); i++) if (coverage.get(i) != 0) n++;
        return n;
    }

    /** The Nuklear font (uploads the atlas as a white texture with the coverage as alpha on first use; needs GL). */
    public NkUserFont userFont() {
        if (font != null) return font;
        upload();
        widthCallback = NkTextWidthCallback.create((handle, h, text, len) ->
                width(StandardCharsets.UTF_8.decode(memByteBuffer(text, len)).toString()));
        queryCallback = NkQueryFontGlyphCallback.create((handle, h, glyph, codePoint, next) -> {
            try (MemoryStack stack = MemoryStack.stackPush()) {
                FloatBuffer x = stack.floats(0f), y = stack.floats(0f);
                STBTTAlignedQuad q = STBTTAlignedQuad.malloc(stack);
                stbtt_GetPackedQuad(chars, ATLAS, ATLAS, drawn(codePoint), x, y, q, false);
                NkUserFontGlyph g = NkUserFontGlyph.create(glyph);
                g.width(q.x1() - q.x0());
                g.height(q.y1() - q.y0());
                g.offset().set(q.x0(), q.y0() + ascent);
                g.xadvance(advance(codePoint));
                g.uv(0).set(q.s0(), q.t0());
                g.uv(1).set(q.s1(), q.t1());
            }
        });
        font = NkUserFont.calloc();
        font.width(widthCallback).height(pixels).query(queryCallback);
        font.texture().id(texture);
        return font;
    }

    private void upload() {
        ByteBuffer rgba = memAlloc(ATLAS * ATLAS * 4);
        try {
            for (int i = 0; i < ATLAS * ATLAS; i++) {
                rgba.put((byte) 0xFF).put((byte) 0xFF).put((byte) 0xFF).put(coverage.get(i));
            }
            rgba.flip();
            texture = glGenTextures();
            glBindTexture(GL_TEXTURE_2D, texture);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, ATLAS, ATLAS, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glBindTexture(GL_TEXTURE_2D, 0);
        } finally {
            memFree(rgba);
        }
        memFree(coverage);
        coverage = null;
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        if (texture != 0) glDeleteTextures(texture);
        if (font != null) font.free();
        if (widthCallback != null) widthCallback.free();
        if (queryCallback != null) queryCallback.free();
        if (coverage != null) memFree(coverage);
        chars.free();
        info.free();
        memFree(ttf);
    }
}
