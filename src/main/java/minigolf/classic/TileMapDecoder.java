package minigolf.classic;

/**
 * Decodes a track's map data (the {@code T} line before any {@code ,Ads:} part).
 *
 * <p>The data is a run of letters, each optionally preceded by a decimal repeat count ({@code 38D}
 * is 38 {@code D}s). The letters A..Z a..z stand for the numbers 0..51. Read tile by tile, row by
 * row from the top left:
 * <ul>
 *   <li>{@code B s f b}: an element tile of shape s with elements f and b;</li>
 *   <li>{@code C s f}: a special tile, special block s on element f; {@code A s f}: an empty tile;</li>
 *   <li>{@code D}..{@code I}: a copy of the tile to the west, north, north-west, two west, two north
 *       and two north-west.</li>
 * </ul>
 * Data that ends exactly after the 24th row leaves the last row out: it is filled with grass, as
 * the original, which starts from an all-grass map, plays it (two public tracks do this). Anything
 * else (an unknown code, a copy from outside the map, a value out of range, data that ends early
 * elsewhere or goes on after the 1,225th tile) is an error that names the tile and the character.
 */
public final class TileMapDecoder {
    private static final String LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    /** No real track repeats a letter more often than the map has characters for. */
    private static final int MAX_REPEAT = 4 * TileMap.TILES;

    private final String data;
    private int pos;        // index in data of the next count or letter
    private int pending;    // copies of 'letter' still to hand out
    private char letter;
    private int letterAt;   // where the current letter stands in data (for messages)

    private TileMapDecoder(String data) {
        this.data = data;
    }

    /**
     * @param data the map data
     * @throws IllegalArgumentException with a message (no file or line) such as
     *         {@code tile 7 (x 6, y 0): 'D' copies the tile to the west, which is outside the map}
     */
    public static TileMap decode(String data) {
        return new TileMapDecoder(data).run();
    }

    private TileMap run() {
        int[] codes = new int[TileMap.TILES];
        for (int t = 0; t < TileMap.TILES; t++) {
            int x = t % TileMap.WIDTH, y = t / TileMap.WIDTH;
            if (t == TileMap.TILES - TileMap.WIDTH && pending == 0 && pos >= data.length()) {
                java.util.Arrays.fill(codes, t, TileMap.TILES, TileMap.GRASS);
                return new TileMap(codes, 1);
            }
            char c = next(t, x, y);
            int v = LETTERS.indexOf(c);
            if (v < 0) throw error(t, x, y, "'" + printable(c) + "' is not a tile code (letters A-I)");
            switch (v) {
                case 0, 1, 2 -> {
                    int a = value(t, x, y), b = value(t, x, y);
                    int d = v == 1 ? value(t, x, y) : 0;
                    if (v == 1) {
                        if (a >= TileMap.SHAPES) throw error(t, x, y, "shape " + a + " does not exist (0-" + (TileMap.SHAPES - 1) + ")");
                        checkElement(b, t, x, y);
                        checkElement(d, t, x, y);
                    } else {
                        if (a >= TileMap.SPECIALS) throw error(t, x, y, "special block " + a + " does not exist (0-" + (TileMap.SPECIALS - 1) + ")");
                        checkElement(b, t, x, y);
                    }
                    codes[t] = v << 24 | a << 16 | b << 8 | d;
                }
                case 3 -> codes[t] = copy(codes, t, x, y, -1, 0, "the tile to the west");
                case 4 -> codes[t] = copy(codes, t, x, y, 0, -1, "the tile to the north");
                case 5 -> codes[t] = copy(codes, t, x, y, -1, -1, "the tile to the north-west");
                case 6 -> codes[t] = copy(codes, t, x, y, -2, 0, "the tile two to the west");
                case 7 -> codes[t] = copy(codes, t, x, y, 0, -2, "the tile two to the north");
                case 8 -> codes[t] = copy(codes, t, x, y, -2, -2, "the tile two to the north-west");
                default -> throw error(t, x, y, "'" + c + "' is not a tile code (letters A-I)");
            }
        }
        if (pending > 0 || pos < data.length()) {
            int at = pending > 0 ? letterAt : pos;
            throw new IllegalArgumentException("the map data goes on after the last of the " + TileMap.TILES
                    + " tiles (at character " + (at + 1) + " of " + data.length() + ")");
        }
        return new TileMap(codes);
    }

    private static int copy(int[] codes, int t, int x, int y, int dx, int dy, String what) {
        int sx = x + dx, sy = y + dy;
        if (sx < 0 || sy < 0) {
            throw error(t, x, y, "'" + "DEFGHI".charAt(codeOf(dx, dy)) + "' copies " + what + ", which is outside the map");
        }
        return codes[sx + TileMap.WIDTH * sy];
    }

    private static int codeOf(int dx, int dy) {
        if (dx == -1 && dy == 0) return 0;
        if (dx == 0 && dy == -1) return 1;
        if (dx == -1) return 2;
        if (dy == 0) return 3;
        if (dx == 0) return 4;
        return 5;
    }

    private int value(int t, int x, int y) {
        char c = next(t, x, y);
        int v = LETTERS.indexOf(c);
        if (v < 0) throw error(t, x, y, "'" + printable(c) + "' is not a value letter (A-Z, a-z)");
        return v;
    }

    private static void checkElement(int e, int t, int x, int y) {
        if (e >= TileMap.ELEMENTS) throw error(t, x, y, "element " + e + " does not exist (0-" + (TileMap.ELEMENTS - 1) + ")");
    }

    /** The next letter of the expanded data. */
    private char next(int t, int x, int y) {
        if (pending > 0) {
            pending--;
            return letter;
        }
        if (pos >= data.length()) {
            throw error(t, x, y, "the map data ends early (" + t + " of " + TileMap.TILES + " tiles read)");
        }
        int start = pos;
        long count = 0;
        while (pos < data.length() && data.charAt(pos) >= '0' && data.charAt(pos) <= '9') {
            count = Math.min(count * 10 + (data.charAt(pos) - '0'), Integer.MAX_VALUE);
            pos++;
        }
        boolean counted = pos > start;
        if (counted && pos >= data.length()) {
            throw error(t, x, y, "the map data ends with a repeat count and no letter (at character " + (start + 1) + ")");
        }
        if (counted && (count < 2 || count > MAX_REPEAT)) {
            throw error(t, x, y, "repeat count " + data.substring(start, pos) + " at character " + (start + 1)
                    + " is not between 2 and " + MAX_REPEAT);
        }
        letter = data.charAt(pos);
        letterAt = pos;
        pos++;
        pending = counted ? (int) count - 1 : 0;
        return letter;
    }

    private static IllegalArgumentException error(int t, int x, int y, String problem) {
        return new IllegalArgumentException("tile " + (t + 1) + " (x " + x + ", y " + y + "): " + problem);
    }

    private static String printable(char c) {
        return c >= 0x20 && c < 0x7F ? String.valueOf(c) : String.format("\\u%04x", (int) c);
    }
}
