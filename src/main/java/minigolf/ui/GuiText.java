package minigolf.ui;

/**
 * Text as the interface draws it: every string handed to Nuklear passes here first, so a name or a
 * message from someone else's file (a 100,000-character course name) is drawn cut short with
 * "..." instead of overflowing LWJGL's small native stack, which the binding encodes each label on.
 * The font has Latin-1 only, so the ellipsis is three dots. No GL: testable with a baked atlas.
 */
public final class GuiText {
    /** The most characters one label keeps before it is measured (no screen shows more on a line). */
    public static final int MAX_CHARS = 400;
    /** Window ids longer than this are replaced by a short hash (Nuklear keeps 64 bytes of a name). */
    static final int MAX_ID_CHARS = 48;
    static final String ELLIPSIS = "...";

    private GuiText() {
    }

    /**
     * {@code text} as it fits in {@code maxWidth} pixels of {@code font}: unchanged when it fits,
     * else its longest start (never splitting a surrogate pair) followed by "...".
     */
    public static String fit(String text, FontAtlas font, float maxWidth) {
        if (text == null) return "";
        String capped = text.length() > MAX_CHARS ? cut(text, MAX_CHARS) : null;
        if (capped == null && font.width(text) <= maxWidth) return text;
        String base = capped != null ? capped : text;
        float room = maxWidth - font.width(ELLIPSIS);
        if (room <= 0) return ELLIPSIS;
        // The longest prefix whose width fits: widths grow with the prefix, so bisect on its length.
        int lo = 0, hi = base.length();
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (font.width(cut(base, mid)) <= room) lo = mid;
            else hi = mid - 1;
        }
        return cut(base, lo) + ELLIPSIS;
    }

    /** A window id of bounded length: itself when short, else its start and a hash of the whole. */
    static String id(String id) {
        if (id.length() <= MAX_ID_CHARS) return id;
        return cut(id, MAX_ID_CHARS - 10) + "#" + Integer.toHexString(id.hashCode());
    }

    /** The first {@code n} characters, one fewer where the n-th would split a surrogate pair. */
    static String cut(String s, int n) {
        if (n >= s.length()) return s;
        if (n > 0 && Character.isHighSurrogate(s.charAt(n - 1))) n--;
        return s.substring(0, n);
    }
}
