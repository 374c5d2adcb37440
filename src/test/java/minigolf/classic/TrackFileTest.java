package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class TrackFileTest {
    static final String GRASS = "B3A48D1176E";

    @Test
    void versionOneTakesItsCategoryFromTheFolder(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("hio").resolve("Someone-Short.track");
        Files.createDirectories(f.getParent());
        Files.writeString(f, Tracks.v1("Someone", "Short one", GRASS));
        ClassicTrack t = TrackFile.read(f);
        assertEquals(1, t.version());
        assertEquals("Someone", t.author());
        assertEquals("Short one", t.name());
        assertEquals(EnumSet.of(TrackCategory.HOLE_IN_ONE), t.categories());
        assertEquals(new TrackStats(10, 35, 2, 1), t.stats());
        assertEquals(3.5, t.stats().averageStrokes(), 1e-12);
        assertEquals("someone", t.firstBest());
        assertEquals(ClassicTrack.DEFAULT_SETTINGS, t.settings());
    }

    @Test
    void versionTwoListsItsCategoriesAndIgnoresTheAdverts() throws Exception {
        ClassicTrack t = TrackFile.parse(Tracks.v2("A. Uthor", "Two", "1,4,6", GRASS, "1000,4321,1,17"), "two.track",
                Optional.of(TrackCategory.MODERN));
        assertEquals(2, t.version());
        assertEquals(EnumSet.of(TrackCategory.BASIC, TrackCategory.HOLE_IN_ONE, TrackCategory.LONG), t.categories());
        assertEquals(new TrackStats(1000, 4321, 1, 17), t.stats());
        assertEquals(4.321, t.stats().averageStrokes(), 1e-12);
        assertEquals(List.of(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11), t.ratings());
        assertEquals("fttt14", t.settings());
        assertEquals(TileMapDecoder.decode(GRASS), t.tiles());
    }

    @Test
    void windowsLineEndsAndUnknownLinesAreFine() throws Exception {
        String text = "V 1\r\nA Me\r\nN Mine\r\nX whatever\r\nT " + GRASS + "\r\n";
        ClassicTrack t = TrackFile.parse(text, "m.track", Optional.empty());
        assertEquals("Mine", t.name());
        assertNull(t.stats());
        assertTrue(t.categories().isEmpty());
    }

    /** A name that parsed (up to 200 characters) but no course may carry (128): refused where it stands. */
    @Test
    void aNameLongerThanACourseNameIsRefusedOnItsLine() {
        String name = "n".repeat(129);
        assertEquals("long.track: line 3 (N): the name is 129 characters long (the limit is 128)",
                assertThrows(TrackFormatException.class,
                        () -> TrackFile.parse(Tracks.v1("Me", name, GRASS), "long.track", Optional.empty())).getMessage());
        assertEquals("n".repeat(128), assertDoesNotThrow(
                () -> TrackFile.parse(Tracks.v1("Me", "n".repeat(128), GRASS), "ok.track", Optional.empty())).name());
    }

    @Test
    void latinOneNamesAreRead(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("x.track");
        Files.write(f, Tracks.v1("Häkkinen", "Öljy", GRASS).getBytes(StandardCharsets.ISO_8859_1));
        ClassicTrack t = TrackFile.read(f);
        assertEquals("Häkkinen", t.author());
        assertEquals("Öljy", t.name());
        Files.write(f, Tracks.v1("Häkkinen", "Öljy", GRASS).getBytes(StandardCharsets.UTF_8));
        assertEquals("Häkkinen", TrackFile.read(f).author());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "A a\\nN n\\nT " + GRASS + "             | t.track: missing the V (version) line",
            "V 1\\nN n\\nT " + GRASS + "             | t.track: missing the A (author) line",
            "V 1\\nA a\\nT " + GRASS + "             | t.track: missing the N (name) line",
            "V 1\\nA a\\nN n                         | t.track: missing the T (map) line",
            "V 1\\nV 1\\nA a\\nN n\\nT " + GRASS + " | t.track: line 2 (V): a second V line",
            "V x\\nA a\\nN n\\nT " + GRASS + "       | t.track: line 1 (V): the version is not a whole number >= 0",
            "V 0\\nA a\\nN n\\nT " + GRASS + "       | t.track: line 1 (V): version 0 does not exist (1 or more)",
            "V 1\\nA \\nN n\\nT " + GRASS + "        | t.track: line 2 (A): the author is empty",
            "V 2\\nA a\\nN n\\nC 9\\nT " + GRASS + " | t.track: line 4 (C): category 9 does not exist (1 basic, 2 traditional, 3 modern, 4 hio, 5 short, 6 long)",
            "V 1\\nA a\\nN n\\nT " + GRASS + "\\nI 1,2,3      | t.track: line 5 (I): expected 4 numbers (plays, strokes, best strokes, players with the best), got 3",
            "V 1\\nA a\\nN n\\nT " + GRASS + "\\nI 1,2,-3,4   | t.track: line 5 (I): number 3 is not a whole number >= 0",
            "V 1\\nA a\\nN n\\nT " + GRASS + "\\nI 5,20,0,1   | t.track: I: best strokes 0 for 5 plays (must be at least 1)",
            "V 1\\nA a\\nN n\\nT " + GRASS + "\\nS ft        | t.track: line 5 (S): expected 6 settings characters, got 2",
            "V 1\\nA a\\nN n\\nT B3A48D1174E        | t.track: line 4 (T): tile 1224 (x 47, y 24): the map data ends early (1223 of 1225 tiles read)",
            "V 1\\nA a\\nN n\\nT B3A48D1176EQ       | t.track: line 4 (T): the map data goes on after the last of the 1225 tiles (at character 12 of 12)",
    })
    void malformedFilesGiveOneLine(String text, String message) {
        TrackFormatException e = assertThrows(TrackFormatException.class,
                () -> TrackFile.parse(text.replace("\\n", "\n"), "t.track", Optional.empty()));
        assertEquals(message, e.getMessage());
        assertTrue(!e.getMessage().contains("\n"));
    }

    @Test
    void binaryAndHugeFilesAreNotTracks(@TempDir Path dir) throws Exception {
        Path bin = dir.resolve("b.track");
        Files.write(bin, new byte[]{'V', ' ', '1', 0, 1, 2});
        assertEquals("b.track: not a track file: binary data",
                assertThrows(TrackFormatException.class, () -> TrackFile.read(bin)).getMessage());
        Path big = dir.resolve("big.track");
        Files.write(big, new byte[(int) TrackFile.MAX_BYTES + 1]);
        assertTrue(assertThrows(TrackFormatException.class, () -> TrackFile.read(big)).getMessage().startsWith("big.track: cannot read"));
    }
}
