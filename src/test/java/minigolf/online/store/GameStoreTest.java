package minigolf.online.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The database, on SQLite and (when {@code MINIGOLF_TEST_POSTGRES_URL} names one, as CI's
 * .ci/online.sh does) on a real PostgreSQL: rooms and events read back, an event is stored once,
 * and the leaderboard keeps each player's best.
 */
class GameStoreTest {
    @TempDir
    Path dir;

    @Test
    void sqlite() throws Exception {
        try (GameStore s = GameStore.open(dir.resolve("a.db").toString())) {
            exercise(s, "R");
        }
        // Reopened: the schema is there and the rooms too.
        try (GameStore s = GameStore.open("jdbc:sqlite:" + dir.resolve("a.db"))) {
            assertEquals(2, s.loadRooms(List.of("finished")).size());
        }
    }

    @Test
    void postgresql() throws Exception {
        String url = System.getenv("MINIGOLF_TEST_POSTGRES_URL");
        assumeTrue(url != null && !url.isBlank(), "MINIGOLF_TEST_POSTGRES_URL is not set (CI's .ci/online.sh sets it)");
        try (GameStore s = GameStore.open(url)) {
            exercise(s, "P" + Long.toString(System.nanoTime() % 1_000_000_000L, 36).toUpperCase());
        }
    }

    @Test
    void aBrokenDatabaseIsOneLine() {
        StoreException e = assertThrows(StoreException.class, () -> GameStore.open("jdbc:postgresql://127.0.0.1:1/x?user=u&password=secret"));
        assertTrue(e.getMessage().startsWith("cannot open the database jdbc:postgresql://127.0.0.1:1/x?user=u&password=..."), e.getMessage());
        assertTrue(!e.getMessage().contains("secret") && !e.getMessage().contains("\n"), e.getMessage());
    }

    private static void exercise(GameStore s, String prefix) throws Exception {
        String room = (prefix + "ROOMXXXX").substring(0, 7) + "0";
        long t = 1_700_000_000_000L;
        s.createRoom(new StoredRoom(room, "lake", true, 10, 2, "lobby", t, null,
                List.of(new StoredSeat(0, "Ann", false, null, "ab".repeat(32), false)), List.of())).get();
        s.addSeat(room, new StoredSeat(1, "Bot", true, "planner", null, false)).get();
        s.startRoom(room, "{\"save\":1}", t + 1).get();
        // Many events at once share transactions (group commit); each completes once stored.
        CompletableFuture<?>[] writes = new CompletableFuture<?>[50];
        for (int i = 0; i < writes.length; i++) {
            writes[i] = s.appendEvent(room, i + 1, "{\"seq\":" + (i + 1) + "}", List.of(), "playing", t + 2 + i);
        }
        CompletableFuture.allOf(writes).get();
        // The same event again is refused: a stroke is stored exactly once.
        ExecutionException dup = assertThrows(ExecutionException.class,
                () -> s.appendEvent(room, 7, "{\"seq\":7}", List.of(), "playing", t).get());
        assertTrue(dup.getCause() instanceof java.sql.SQLException, String.valueOf(dup.getCause()));
        s.appendEvent(room, 51, "{\"seq\":51}", List.of(
                new Score("lake", "Ann", null, 5, 3, room, 0, t + 100),
                new Score("lake", "Bot", "planner", 2, 3, room, 1, t + 100)), "finished", t + 100).get();

        StoredRoom back = s.loadRooms(List.of("finished")).stream().filter(r -> r.code().equals(room)).findFirst().orElseThrow();
        assertEquals("{\"save\":1}", back.startSave());
        assertEquals(51, back.events().size());
        for (int i = 0; i < 51; i++) assertEquals("{\"seq\":" + (i + 1) + "}", back.events().get(i));
        assertEquals(List.of("Ann", "Bot"), back.seatList().stream().map(StoredSeat::name).toList());
        assertEquals("ab".repeat(32), back.seatList().get(0).tokenHash());
        assertEquals("planner", back.seatList().get(1).level());

        // A second, better round by Ann: the board shows each player's best once, fewest strokes first.
        String room2 = (prefix + "ROOMXXXX").substring(0, 7) + "1";
        s.createRoom(new StoredRoom(room2, "lake", true, 10, 1, "playing", t, "{}", List.of(), List.of())).get();
        s.appendEvent(room2, 1, "{}", List.of(new Score("lake", "Ann", null, 3, 3, room2, 0, t + 200)), "finished", t + 200).get();
        List<Score> board = s.leaderboard("lake", 10).get();
        assertEquals(List.of("Bot", "Ann"), board.stream().map(Score::name).toList());
        assertEquals(List.of(2, 3), board.stream().map(Score::strokes).toList());
        assertEquals(List.of(), s.leaderboard("no-such-course", 10).get());
    }
}
