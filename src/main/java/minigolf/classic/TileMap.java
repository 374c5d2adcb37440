package minigolf.classic;

import java.util.Arrays;

/**
 * The 49 x 25 tiles of a track, each a 32-bit code as the original packs it:
 * {@code kind << 24 | shape << 16 | first << 8 | second}.
 *
 * <ul>
 *   <li>kind 1, an <em>element tile</em>: shape {@code shape} (0..27) of the shapes sheet; where the
 *       shape's mask is set the tile is element {@code first}, elsewhere element {@code second}
 *       (elements 0..23: grass, sand, mud, ice, eight downhills, water, acid, shallow water and
 *       acid, block, sticky, bouncy, illusion wall, four one-way walls).</li>
 *   <li>kind 2, a <em>special tile</em>: special block {@code shape} (0..27: start, hole, movable
 *       block, mines, teleports, breakable bricks, magnets, coloured starts) on element {@code first}.</li>
 *   <li>kind 0 (code letter A): an empty tile, which the original collides with as grass.</li>
 * </ul>
 */
public final class TileMap {
    public static final int WIDTH = 49;
    public static final int HEIGHT = 25;
    public static final int TILES = WIDTH * HEIGHT;
    public static final int ELEMENT_TILE = 1;
    public static final int SPECIAL_TILE = 2;
    public static final int SHAPES = 28;
    public static final int ELEMENTS = 24;
    public static final int SPECIALS = 28;
    /** Plain grass: an element tile of shape 0 with grass on both sides. */
    public static final int GRASS = ELEMENT_TILE << 24;

    private final int[] codes;
    private final int filledRows;

    /** @param codes 1225 codes, row by row (index x + 49 y); copied */
    public TileMap(int[] codes) {
        this(codes, 0);
    }

    /**
     * @param filledRows how many rows at the bottom the data left out and the decoder filled with
     *        grass (0 or 1, see {@link TileMapDecoder})
     */
    public TileMap(int[] codes, int filledRows) {
        if (codes.length != TILES) throw new IllegalArgumentException("a track has " + TILES + " tiles, got " + codes.length);
        this.codes = codes.clone();
        this.filledRows = filledRows;
    }

    /** How many rows at the bottom the data left out (filled with grass): 0 for a complete map. */
    public int filledRows() {
        return filledRows;
    }

    public int code(int x, int y) {
        return codes[x + WIDTH * y];
    }

    public static int kind(int code) {
        return code >>> 24;
    }

    public static int shape(int code) {
        return (code >>> 16) & 0xFF;
    }

    public static int first(int code) {
        return (code >>> 8) & 0xFF;
    }

    public static int second(int code) {
        return code & 0xFF;
    }

    public static int elementTile(int shape, int first, int second) {
        return ELEMENT_TILE << 24 | shape << 16 | first << 8 | second;
    }

    public static int specialTile(int special, int background) {
        return SPECIAL_TILE << 24 | special << 16 | background << 8;
    }

    /** A copy of the codes, row by row. */
    public int[] codes() {
        return codes.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof TileMap t && Arrays.equals(codes, t.codes);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(codes);
    }
}
