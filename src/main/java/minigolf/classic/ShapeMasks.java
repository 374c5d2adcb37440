package minigolf.classic;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * The 15 x 15 pixel masks of the 28 element shapes ({@code shapes.gif}) and the 28 special blocks
 * ({@code special.gif}). A mask pixel is set where the original's sprite has the colour 0xCCCCFF:
 * there an element tile shows its first element, a special tile its background element.
 *
 * <p>The exact masks are only in the original game's images, which are not ours to ship: read them
 * with {@link #fromImages} from a player's copy. {@link #builtIn()} is an approximation inferred
 * from how real tracks use each shape (which sides carry which element, how tiles chain): good
 * enough to play, not a faithful copy (docs/classic-tracks.md says which shapes are guesses).
 */
public final class ShapeMasks {
    public static final int SIZE = 15;
    /** The sprite sheets' key colour: where a sprite has it, the mask is set. */
    public static final int MASK_COLOUR = 0xCCCCFF;
    private static final int PER_ROW = 4;
    private static final int COUNT = 28;
    /** A sheet of 4 x 7 sprites of 15 px with 1 px separators. */
    public static final int SHEET_WIDTH = PER_ROW * (SIZE + 1) + 1;
    public static final int SHEET_HEIGHT = COUNT / PER_ROW * (SIZE + 1) + 1;
    /** Largest image file read (the originals are about 2 KB). */
    private static final long MAX_IMAGE_BYTES = 1 << 20;

    private final boolean[][] shapes;
    private final boolean[][] specials;
    private final String source;

    private ShapeMasks(boolean[][] shapes, boolean[][] specials, String source) {
        this.shapes = shapes;
        this.specials = specials;
        this.source = source;
    }

    /** Whether element shape {@code shape}'s mask is set at pixel (x, y) of the tile. */
    public boolean shape(int shape, int x, int y) {
        return shapes[shape][x + SIZE * y];
    }

    /** Whether special block {@code special}'s mask (its background) is set at pixel (x, y). */
    public boolean special(int special, int x, int y) {
        return specials[special][x + SIZE * y];
    }

    /** Where the masks came from: {@code "built-in approximation"} or the image files read. */
    public String source() {
        return source;
    }

    public boolean exact() {
        return !source.equals(BUILT_IN);
    }

    private static final String BUILT_IN = "built-in approximation";

    /** Reads {@code shapes.gif} and {@code special.gif} from a folder. */
    public static ShapeMasks fromImages(Path folder) throws TrackFormatException {
        Path shapes = folder.resolve("shapes.gif"), special = folder.resolve("special.gif");
        return new ShapeMasks(readSheet(shapes), readSheet(special), shapes + ", " + special);
    }

    /**
     * Reads one sprite sheet: 28 sprites of 15 x 15 px, 4 to a row, each with a 1 px border.
     *
     * @throws TrackFormatException one line naming the file and what is wrong
     */
    public static boolean[][] readSheet(Path file) throws TrackFormatException {
        BufferedImage image;
        try {
            if (!Files.isRegularFile(file)) throw new TrackFormatException(file + ": no such image file");
            if (Files.size(file) > MAX_IMAGE_BYTES) {
                throw new TrackFormatException(file + ": too large for a sprite sheet (" + Files.size(file) + " bytes)");
            }
            try (InputStream in = Files.newInputStream(file)) {
                image = ImageIO.read(in);
            }
        } catch (javax.imageio.IIOException | RuntimeException e) {
            // The image readers' messages name their own internals ("Empty region!", a class name): not the player's problem.
            throw new TrackFormatException(file + ": cannot read the image: damaged, or not a GIF or PNG");
        } catch (IOException e) {
            throw new TrackFormatException(file + ": cannot read the image: " + e.getMessage());
        }
        if (image == null) throw new TrackFormatException(file + ": not an image Java can read (GIF or PNG)");
        if (image.getWidth() < SHEET_WIDTH || image.getHeight() < SHEET_HEIGHT) {
            throw new TrackFormatException(file + ": expected a sheet of 4 x 7 sprites of 15 px (at least "
                    + SHEET_WIDTH + " x " + SHEET_HEIGHT + " px), got " + image.getWidth() + " x " + image.getHeight());
        }
        boolean[][] masks = new boolean[COUNT][SIZE * SIZE];
        for (int i = 0; i < COUNT; i++) {
            int row = i / PER_ROW, column = i % PER_ROW;
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    int rgb = image.getRGB(column * (SIZE + 1) + 1 + x, row * (SIZE + 1) + 1 + y) & 0xFFFFFF;
                    masks[i][x + SIZE * y] = rgb == MASK_COLOUR;
                }
            }
        }
        return masks;
    }

    /** Masks from explicit arrays (tests; 28 masks of 225 pixels each). */
    public static ShapeMasks of(boolean[][] shapes, boolean[][] specials, String source) {
        if (shapes.length != COUNT || specials.length != COUNT) throw new IllegalArgumentException("28 masks each");
        return new ShapeMasks(shapes.clone(), specials.clone(), source);
    }

    /**
     * The approximation used without the images (docs/classic-tracks.md). Shapes: 0 full; 1-3 a
     * round post of the second element (radius 6.5, 4.5, 2.5 px); 4-7 diagonal halves, the first
     * element in the NW, NE, SE, SW corner; 8-11 the same, the second element a quarter disc
     * centred on the opposite corner (radius 15: a block's rounded corner); 12-15 a small bump of the second element on the S, W, N, E edge; 16-19 a
     * half disc of the second element on the S, W, N, E edge; 20 a round post of the first element;
     * 21 a vertical strip of the first element; 22 the right half, 23 the top half; 24-27 the
     * corners of the map's frame (bottom-left, top-left, top-right, bottom-right: top or bottom half
     * plus left or right half, the inner corner rounded). Specials: discs for the hole, mines,
     * teleports and markers, full tiles for blocks.
     */
    public static ShapeMasks builtIn() {
        boolean[][] s = new boolean[COUNT][SIZE * SIZE];
        boolean[][] p = new boolean[COUNT][SIZE * SIZE];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                int i = x + SIZE * y;
                double cx = x + 0.5, cy = y + 0.5;
                double r = Math.hypot(cx - 7.5, cy - 7.5);
                s[0][i] = true;
                s[1][i] = r >= 6.5;
                s[2][i] = r >= 4.5;
                s[3][i] = r >= 2.5;
                s[4][i] = x + y <= 14;
                s[5][i] = y <= x;
                s[6][i] = x + y >= 14;
                s[7][i] = y >= x;
                s[8][i] = Math.hypot(15 - cx, 15 - cy) > 15;
                s[9][i] = Math.hypot(cx, 15 - cy) > 15;
                s[10][i] = Math.hypot(cx, cy) > 15;
                s[11][i] = Math.hypot(15 - cx, cy) > 15;
                s[12][i] = Math.hypot(cx - 7.5, 15 - cy) > 4.5;
                s[13][i] = Math.hypot(cx, cy - 7.5) > 4.5;
                s[14][i] = Math.hypot(cx - 7.5, cy) > 4.5;
                s[15][i] = Math.hypot(15 - cx, cy - 7.5) > 4.5;
                s[16][i] = Math.hypot(cx - 7.5, 15 - cy) > 7.5;
                s[17][i] = Math.hypot(cx, cy - 7.5) > 7.5;
                s[18][i] = Math.hypot(cx - 7.5, cy) > 7.5;
                s[19][i] = Math.hypot(15 - cx, cy - 7.5) > 7.5;
                s[20][i] = r < 4.5;
                s[21][i] = x >= 5 && x <= 9;
                s[22][i] = x >= 7;
                s[23][i] = y <= 7;
                // Frame corners: the frame's halves, the inner corner rounded with radius 7.5.
                s[24][i] = corner(cx, cy, false, true);
                s[25][i] = corner(cx, cy, true, true);
                s[26][i] = corner(cx, cy, true, false);
                s[27][i] = corner(cx, cy, false, false);
                boolean disc7 = r >= 7.2, disc5 = r >= 5.0, disc4 = r >= 4.5, disc6 = r >= 6.5, dot = r >= 2.5;
                p[0][i] = true;             // start: the background everywhere (the original overrides it too)
                p[1][i] = disc7;            // hole
                p[2][i] = disc7;            // fake hole (drawn only)
                p[3][i] = false;            // movable block: the whole tile
                p[4][i] = disc4;            // mine
                p[5][i] = disc4;
                p[6][i] = disc5;            // big mine
                p[7][i] = disc5;
                for (int t = 8; t <= 15; t++) p[t][i] = disc6; // teleport starts and exits
                for (int t = 16; t <= 19; t++) p[t][i] = false; // bricks: the whole tile
                p[20][i] = disc6;           // magnets
                p[21][i] = disc6;
                p[22][i] = false;           // sinkable movable block
                p[23][i] = false;           // sunk block
                for (int t = 24; t <= 27; t++) p[t][i] = dot; // coloured starts
            }
        }
        return new ShapeMasks(s, p, BUILT_IN);
    }

    /** A frame corner: the top (or bottom) half and the left (or right) half, inner corner rounded. */
    private static boolean corner(double cx, double cy, boolean top, boolean left) {
        double ix = left ? cx : 15 - cx, iy = top ? cy : 15 - cy; // distances from the outer edges
        if (ix <= 7.5 || iy <= 7.5) return true;
        return Math.hypot(ix - 15, iy - 15) >= 7.5;
    }
}
