package minigolf.classic;

/**
 * The track as the original client sees it: 735 x 375 pixels, each one value, built tile by tile
 * the way the original builds its collision map. Values 0..23 are elements (0 grass, 1 sand, 2 mud,
 * 3 ice, 4..11 downhill N, NE, E, SE, S, SW, W, NW, 12 water, 13 acid, 14 shallow water, 15 shallow
 * acid, 16 block, 17 sticky block, 18 bouncy block, 19 illusion block, 20..23 one-way N, E, S, W);
 * 24 + s is special block s where its mask is clear (25 hole, 27 movable block, 28 mine, 30 big
 * mine, 32/34/36/38 teleport starts, 40..43 bricks, 44 attracting magnet, 46 sinkable block, ...).
 * Start positions, teleport exits, the fake hole and the repelling magnet leave their background.
 */
public final class PixelMap {
    public static final int TILE = ShapeMasks.SIZE;
    public static final int WIDTH = TileMap.WIDTH * TILE;
    public static final int HEIGHT = TileMap.HEIGHT * TILE;

    public static final int GRASS = 0, SAND = 1, MUD = 2, ICE = 3, DOWNHILL_N = 4, DOWNHILL_NW = 11;
    public static final int WATER = 12, ACID = 13, SHALLOW_WATER = 14, SHALLOW_ACID = 15;
    public static final int BLOCK = 16, STICKY = 17, BOUNCY = 18, ILLUSION = 19, ONE_WAY_N = 20, ONE_WAY_W = 23;
    public static final int SPECIAL = 24;
    public static final int HOLE = 25, MOVABLE = 27, MINE = 28, MINE_SPENT = 29, BIG_MINE = 30, BIG_MINE_SPENT = 31;
    public static final int TELEPORT_BLUE = 32, TELEPORT_GREEN = 38;
    public static final int BRICK_FULL = 40, BRICK_QUARTER = 43, MAGNET = 44, REPELLER = 45, SINKABLE = 46, SUNK = 47;

    private final byte[] values;

    private PixelMap(byte[] values) {
        this.values = values;
    }

    public static PixelMap of(TileMap tiles, ShapeMasks masks) {
        byte[] v = new byte[WIDTH * HEIGHT];
        for (int ty = 0; ty < TileMap.HEIGHT; ty++) {
            for (int tx = 0; tx < TileMap.WIDTH; tx++) {
                paintTile(v, tx, ty, tiles.code(tx, ty), masks);
            }
        }
        return new PixelMap(v);
    }

    /** The value at pixel (x, y); outside the map, a block (the original clamps the ball inside). */
    public int at(int x, int y) {
        if (x < 0 || y < 0 || x >= WIDTH || y >= HEIGHT) return BLOCK;
        return values[x + WIDTH * y];
    }

    /** Which pixels (index x + WIDTH y) hold one of {@code values}. */
    public boolean[] where(int... values) {
        boolean[] set = new boolean[WIDTH * HEIGHT];
        for (int i = 0; i < set.length; i++) {
            for (int v : values) set[i] |= this.values[i] == v;
        }
        return set;
    }

    /** The pixel value of one tile's pixel (x, y), 0..14 each, as the original computes it. */
    public static int pixel(int code, int x, int y, ShapeMasks masks) {
        int kind = TileMap.kind(code), shape = TileMap.shape(code), first = TileMap.first(code);
        if (kind == TileMap.ELEMENT_TILE) return masks.shape(shape, x, y) ? first : TileMap.second(code);
        if (kind != TileMap.SPECIAL_TILE) return GRASS; // an empty tile collides as grass
        int s = SPECIAL + shape;
        if (s == 24 || s == 26 || s == 33 || s == 35 || s == 37 || s == 39 || s == REPELLER) return first;
        if (s >= BRICK_FULL && s <= BRICK_QUARTER) return s;
        if (s == MAGNET) return first >= WATER && first <= SHALLOW_ACID ? first : MAGNET;
        return masks.special(shape, x, y) ? first : s;
    }

    private static void paintTile(byte[] v, int tx, int ty, int code, ShapeMasks masks) {
        for (int y = 0; y < TILE; y++) {
            for (int x = 0; x < TILE; x++) {
                v[tx * TILE + x + WIDTH * (ty * TILE + y)] = (byte) pixel(code, x, y, masks);
            }
        }
    }

    /** Whether the original's ball bounces off this value (the breakable bricks and movable blocks included). */
    public static boolean solid(int value) {
        return value >= BLOCK && value <= ONE_WAY_W && value != ILLUSION
                || value == MOVABLE || value >= BRICK_FULL && value <= BRICK_QUARTER || value == SINKABLE;
    }
}
