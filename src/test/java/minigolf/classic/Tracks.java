package minigolf.classic;

import java.util.Arrays;

/**
 * Tracks written for the tests from the format description (docs/classic-tracks.md): no real
 * track is used. Maps are built tile by tile and written out in full (B s f b, C s f, A s f), or
 * by hand where a test is about repeats and copies.
 */
final class Tracks {
    static final String LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

    private Tracks() {
    }

    static char letter(int v) {
        return LETTERS.charAt(v);
    }

    /** A map of plain grass. */
    static int[] grass() {
        int[] codes = new int[TileMap.TILES];
        Arrays.fill(codes, TileMap.GRASS);
        return codes;
    }

    static void set(int[] codes, int x, int y, int code) {
        codes[x + TileMap.WIDTH * y] = code;
    }

    /** The tile's code as the file writes it, without repeats or copies. */
    static String tile(int code) {
        int kind = TileMap.kind(code);
        char s = letter(TileMap.shape(code)), f = letter(TileMap.first(code));
        return switch (kind) {
            case TileMap.ELEMENT_TILE -> "B" + s + f + letter(TileMap.second(code));
            case TileMap.SPECIAL_TILE -> "C" + s + f;
            default -> "A" + s + f;
        };
    }

    /** The whole map written tile by tile. */
    static String encode(int[] codes) {
        StringBuilder sb = new StringBuilder();
        for (int c : codes) sb.append(tile(c));
        return sb.toString();
    }

    /** A V1 file (its category comes from its folder). */
    static String v1(String author, String name, String data) {
        return "V 1\nA " + author + "\nN " + name + "\nT " + data + "\nI 10,35,2,1\nB someone,1100000000000\n";
    }

    /** A V2 file with categories, statistics, ratings and settings. */
    static String v2(String author, String name, String categories, String data, String stats) {
        return "V 2\nA " + author + "\nN " + name + "\nC " + categories + "\nT " + data + ",Ads:B0000\nI " + stats
                + "\nB someone,1100000000000\nL other,1200000000000\nR 1,2,3,4,5,6,7,8,9,10,11\nS fttt14\n";
    }

    /**
     * A playable map: a frame of blocks, the start at tile (4, 12), the hole at tile (44, 12), grass
     * between. Tests paint their elements on it.
     */
    static int[] framed() {
        int[] codes = grass();
        int block = TileMap.elementTile(0, PixelMap.BLOCK, PixelMap.BLOCK);
        for (int x = 0; x < TileMap.WIDTH; x++) {
            set(codes, x, 0, block);
            set(codes, x, TileMap.HEIGHT - 1, block);
        }
        for (int y = 0; y < TileMap.HEIGHT; y++) {
            set(codes, 0, y, block);
            set(codes, TileMap.WIDTH - 1, y, block);
        }
        set(codes, 4, 12, TileMap.specialTile(0, PixelMap.GRASS));
        set(codes, 44, 12, TileMap.specialTile(1, PixelMap.GRASS));
        return codes;
    }
}
