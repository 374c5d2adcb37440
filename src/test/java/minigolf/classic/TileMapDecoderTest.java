package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class TileMapDecoderTest {
    /** Every element tile code, every special and the empty tile, written out in full, decode to themselves. */
    @Test
    void everyTileCodeWrittenInFull() {
        int[] codes = new int[TileMap.TILES];
        int i = 0;
        for (int shape = 0; shape < TileMap.SHAPES; shape++) {
            for (int e = 0; e < TileMap.ELEMENTS; e++) {
                codes[i++] = TileMap.elementTile(shape, e, (e * 7 + shape) % TileMap.ELEMENTS);
            }
        }
        // 672 element tiles; then each special on each of a few elements, then empty tiles.
        for (int s = 0; s < TileMap.SPECIALS; s++) {
            for (int e = 0; e < TileMap.ELEMENTS; e += 3) codes[i++] = TileMap.specialTile(s, e);
        }
        for (; i < TileMap.TILES; i++) codes[i] = (i % TileMap.SPECIALS) << 16 | (i % TileMap.ELEMENTS) << 8; // "A s f"
        TileMap map = TileMapDecoder.decode(Tracks.encode(codes));
        assertArrayEquals(codes, map.codes());
        assertEquals(0, map.filledRows());
    }

    @Test
    void repeatCountsRepeatTheNextLetter() {
        TileMap plain = TileMapDecoder.decode(Tracks.encode(Tracks.grass()));
        // "B3A" is "BAAA"; "48D" copies the first tile along the row; "1176E" copies each row down.
        assertEquals(plain, TileMapDecoder.decode("B3A48D1176E"));
        assertEquals(plain, TileMapDecoder.decode("BAAAB3A47D1176E"));
    }

    /**
     * A repeated letter is only letters: "6A" is two empty tiles "AAA" "AAA". Copies do not wrap
     * round rows: a 'D' at the start of a row is an error (no public track in the sample has one).
     */
    @Test
    void aRepeatedLetterMaySpanTiles() {
        int[] expected = Tracks.grass();
        for (int y = 0; y < TileMap.HEIGHT; y++) {
            expected[TileMap.WIDTH * y] = 0;
            expected[TileMap.WIDTH * y + 1] = 0;
        }
        assertArrayEquals(expected, TileMapDecoder.decode("6ABAAA46D1176E").codes());
    }

    /** Each copy code takes the tile it names: west, north, north-west, two west, two north, two north-west. */
    @Test
    void everyCopyCode() {
        SplittableRandom r = new SplittableRandom(28);
        int[] source = new int[TileMap.WIDTH * 2];
        for (int k = 0; k < source.length; k++) {
            source[k] = TileMap.elementTile(r.nextInt(TileMap.SHAPES), r.nextInt(TileMap.ELEMENTS), r.nextInt(TileMap.ELEMENTS));
        }
        StringBuilder data = new StringBuilder(Tracks.encode(source));
        // Row 2: at x = 2.. the codes D E F G H I in turn, then grass.
        String copies = "DEFGHI";
        int[] expected = Tracks.grass();
        System.arraycopy(source, 0, expected, 0, source.length);
        int w = TileMap.WIDTH;
        expected[2 * w] = source[0];
        expected[2 * w + 1] = source[1];
        data.append(Tracks.tile(source[0])).append(Tracks.tile(source[1]));
        for (int k = 0; k < 6; k++) {
            int x = 2 + k, at = 2 * w + x;
            int from = switch (copies.charAt(k)) {
                case 'D' -> at - 1;
                case 'E' -> at - w;
                case 'F' -> at - w - 1;
                case 'G' -> at - 2;
                case 'H' -> at - 2 * w;
                default -> at - 2 * w - 2;
            };
            expected[at] = expected[from];
            data.append(copies.charAt(k));
        }
        for (int at = 2 * w + 8; at < TileMap.TILES; at++) data.append("BAAA");
        assertArrayEquals(expected, TileMapDecoder.decode(data.toString()).codes());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "J3A1224D          | tile 1 (x 0, y 0): 'J' is not a tile code (letters A-I)",
            "D                 | tile 1 (x 0, y 0): 'D' copies the tile to the west, which is outside the map",
            "BAAAE             | tile 2 (x 1, y 0): 'E' copies the tile to the north, which is outside the map",
            "BAAAF             | tile 2 (x 1, y 0): 'F' copies the tile to the north-west, which is outside the map",
            "BAAAG             | tile 2 (x 1, y 0): 'G' copies the tile two to the west, which is outside the map",
            "B3A48DH           | tile 50 (x 0, y 1): 'H' copies the tile two to the north, which is outside the map",
            "B3A48DBAAAI       | tile 51 (x 1, y 1): 'I' copies the tile two to the north-west, which is outside the map",
            "BcAA              | tile 1 (x 0, y 0): shape 28 does not exist (0-27)",
            "BAYA              | tile 1 (x 0, y 0): element 24 does not exist (0-23)",
            "BAAY              | tile 1 (x 0, y 0): element 24 does not exist (0-23)",
            "CcA               | tile 1 (x 0, y 0): special block 28 does not exist (0-27)",
            "CAY               | tile 1 (x 0, y 0): element 24 does not exist (0-23)",
            "BA!A              | tile 1 (x 0, y 0): '!' is not a value letter (A-Z, a-z)",
            "B3A               | tile 2 (x 1, y 0): the map data ends early (1 of 1225 tiles read)",
            "B3A48D1175E       | tile 1225 (x 48, y 24): the map data ends early (1224 of 1225 tiles read)",
            "BA3               | tile 1 (x 0, y 0): the map data ends with a repeat count and no letter (at character 3)",
            "1BAAA             | tile 1 (x 0, y 0): repeat count 1 at character 1 is not between 2 and 4900",
            "B3A99999D         | tile 2 (x 1, y 0): repeat count 99999 at character 4 is not between 2 and 4900",
            "B3A48D1176EE      | the map data goes on after the last of the 1225 tiles (at character 12 of 12)",
            "B3A48D1177E       | the map data goes on after the last of the 1225 tiles (at character 11 of 11)",
    })
    void malformedMapsNameTheTileAndTheProblem(String data, String message) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TileMapDecoder.decode(data));
        assertEquals(message, e.getMessage());
    }

    /** Two public tracks end after row 24: the last row is filled with grass (as the original's empty map). */
    @Test
    void dataEndingAfterRow24FillsTheLastRow() {
        int[] codes = Tracks.grass();
        for (int x = 0; x < TileMap.WIDTH; x++) Tracks.set(codes, x, 23, TileMap.elementTile(0, PixelMap.WATER, 0));
        String data = Tracks.encode(Arrays.copyOf(codes, TileMap.TILES - TileMap.WIDTH));
        TileMap map = TileMapDecoder.decode(data);
        assertEquals(1, map.filledRows());
        assertArrayEquals(codes, map.codes());
        // One tile into the last row is not a whole row: an error.
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TileMapDecoder.decode(data + "BAAA"));
        assertTrue(e.getMessage().contains("ends early (1177 of 1225"), e.getMessage());
    }
}
