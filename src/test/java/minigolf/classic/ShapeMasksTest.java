package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The sprite-sheet reader, on sheets drawn here (the original images are not part of the project). */
class ShapeMasksTest {
    /** A pattern that differs between sprites and pixels. */
    static boolean pattern(int sprite, int x, int y, int salt) {
        return ((x * 7 + y * 3 + sprite * 5 + salt) % 4) == 0 || x == sprite % 15;
    }

    /** Writes a 4 x 7 sheet of 15 px sprites with 1 px black separators: key colour where the pattern is set. */
    static void writeSheet(Path file, int salt, int width, int height) throws Exception {
        byte[] r = {0, (byte) 0xCC, (byte) 0x40, (byte) 0x99}, g = {0, (byte) 0xCC, (byte) 0x80, (byte) 0x33},
                b = {0, (byte) 0xFF, (byte) 0x40, (byte) 0x11};
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_BYTE_INDEXED,
                new IndexColorModel(2, 4, r, g, b));
        for (int i = 0; i < 28; i++) {
            int ox = (i % 4) * 16 + 1, oy = (i / 4) * 16 + 1;
            for (int y = 0; y < 15; y++) {
                for (int x = 0; x < 15; x++) {
                    image.setRGB(ox + x, oy + y, pattern(i, x, y, salt) ? 0xFFCCCCFF : (x + y) % 2 == 0 ? 0xFF408040 : 0xFF993311);
                }
            }
        }
        assertTrue(ImageIO.write(image, "gif", file.toFile()));
    }

    @Test
    void readsBothSheetsFromAFolder(@TempDir Path dir) throws Exception {
        writeSheet(dir.resolve("shapes.gif"), 0, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT);
        writeSheet(dir.resolve("special.gif"), 1, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT);
        ShapeMasks m = ShapeMasks.fromImages(dir);
        assertTrue(m.exact());
        for (int i = 0; i < 28; i++) {
            for (int y = 0; y < 15; y++) {
                for (int x = 0; x < 15; x++) {
                    assertEquals(pattern(i, x, y, 0), m.shape(i, x, y), "shape " + i + " at " + x + "," + y);
                    assertEquals(pattern(i, x, y, 1), m.special(i, x, y), "special " + i + " at " + x + "," + y);
                }
            }
        }
        assertTrue(m.source().contains("shapes.gif") && m.source().contains("special.gif"));
    }

    @Test
    void theImagesAreFoundBesideTheTracks(@TempDir Path dir) throws Exception {
        Path images = dir.resolve("client").resolve("picture").resolve("agolf");
        Files.createDirectories(images);
        Files.createDirectories(dir.resolve("tracks").resolve("basic"));
        writeSheet(images.resolve("shapes.gif"), 0, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT);
        writeSheet(images.resolve("special.gif"), 1, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT);
        assertEquals(images, ShapeImages.locate(dir.resolve("tracks")).orElseThrow());
    }

    @Test
    void badSheetsGiveOneLine(@TempDir Path dir) throws Exception {
        Path missing = dir.resolve("none.gif");
        assertEquals(missing + ": no such image file",
                assertThrows(TrackFormatException.class, () -> ShapeMasks.readSheet(missing)).getMessage());
        Path small = dir.resolve("small.gif");
        writeSheet(small, 0, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT - 1);
        assertEquals(small + ": expected a sheet of 4 x 7 sprites of 15 px (at least 65 x 113 px), got 65 x 112",
                assertThrows(TrackFormatException.class, () -> ShapeMasks.readSheet(small)).getMessage());
        Path text = dir.resolve("text.gif");
        Files.writeString(text, "GIF89a? not really");
        String m = assertThrows(TrackFormatException.class, () -> ShapeMasks.readSheet(text)).getMessage();
        assertTrue(m.startsWith(text + ": "), m);
        assertFalse(m.contains("\n"));
    }

    /** A sheet whose image is 0 px wide: the reader's own words ("java.lang.IllegalArgumentException: Empty region!") were shown. */
    @Test
    void aDamagedSheetIsNamedInThePlayersWords(@TempDir Path dir) throws Exception {
        Path sheet = dir.resolve("shapes.gif");
        writeSheet(sheet, 0, ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT);
        byte[] gif = Files.readAllBytes(sheet);
        int descriptor = 13 + ((gif[10] & 0x80) != 0 ? 3 * (2 << (gif[10] & 7)) : 0); // past the global colour table
        while (gif[descriptor] == 0x21) { // an extension: its label, then sub-blocks up to an empty one
            descriptor += 2;
            while (gif[descriptor] != 0) descriptor += 1 + (gif[descriptor] & 0xFF);
            descriptor++;
        }
        assertEquals(0x2C, gif[descriptor], "the image descriptor");
        gif[descriptor + 5] = 0;
        gif[descriptor + 6] = 0;
        Files.write(sheet, gif);
        assertEquals(sheet + ": cannot read the image: damaged, or not a GIF or PNG",
                assertThrows(TrackFormatException.class, () -> ShapeMasks.readSheet(sheet)).getMessage());
    }

    /** The built-in approximation: the shapes whose form the format description fixes. */
    @Test
    void builtInShapes() {
        ShapeMasks m = ShapeMasks.builtIn();
        assertFalse(m.exact());
        assertEquals(225, count(m, 0));
        // Diagonal halves: the first element in the NW, NE, SE, SW corner, the diagonal on the first's side.
        for (int s = 4; s <= 7; s++) assertEquals(120, count(m, s), "shape " + s);
        assertTrue(m.shape(4, 0, 0) && !m.shape(4, 14, 14));
        assertTrue(m.shape(5, 14, 0) && !m.shape(5, 0, 14));
        assertTrue(m.shape(6, 14, 14) && !m.shape(6, 0, 0));
        assertTrue(m.shape(7, 0, 14) && !m.shape(7, 14, 0));
        // Rounded corners: a quarter disc of radius 15 is about pi/4 of the tile.
        for (int s = 8; s <= 11; s++) {
            int second = 225 - count(m, s);
            assertEquals(Math.PI / 4 * 225, second, 6, "shape " + s);
        }
        // Specials: the start is background everywhere; a hole is a disc; bricks are whole tiles.
        assertTrue(m.special(0, 7, 7));
        assertFalse(m.special(1, 7, 7));
        assertTrue(m.special(1, 0, 0));
        assertFalse(m.special(16, 0, 0));
    }

    private static int count(ShapeMasks m, int shape) {
        int n = 0;
        for (int y = 0; y < 15; y++) for (int x = 0; x < 15; x++) if (m.shape(shape, x, y)) n++;
        return n;
    }
}
