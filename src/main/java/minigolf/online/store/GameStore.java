package minigolf.online.store;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;

/**
 * The server's database: rooms, seats, every event of every room, and the scores behind the
 * leaderboards (docs/online.md, "Database"). SQLite (xerial sqlite-jdbc) by default, a PostgreSQL
 * JDBC URL for a shared server; the same SQL for both.
 *
 * <p>One thread owns the connection and runs every task in order. Tasks that queue up while a
 * transaction commits go into the next transaction together (group commit), so a busy server pays
 * one commit for many strokes; a task's future completes only once its transaction is committed,
 * which is when the server tells the players.
 */
public final class GameStore implements AutoCloseable {
    /** Raised when the tables change; the schema says which version made it. */
    static final int SCHEMA_VERSION = 1;
    private static final int MAX_BATCH = 256;

    /** Work for the database thread. */
    @FunctionalInterface
    public interface Work<T> {
        T run(Connection c) throws SQLException;
    }

    private record Task<T>(Work<T> work, CompletableFuture<T> done) {
    }

    private final String description;
    private final Connection connection;
    private final BlockingQueue<Task<?>> queue = new LinkedBlockingQueue<>();
    private final Thread thread;
    private volatile boolean closed;

    private GameStore(String description, Connection connection) {
        this.description = description;
        this.connection = connection;
        thread = new Thread(this::loop, "minigolf-db");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Opens (and if new, creates) the database: a file name for SQLite, or a JDBC URL
     * ({@code jdbc:sqlite:FILE}, {@code jdbc:postgresql://HOST/DB?user=U&password=P}).
     */
    public static GameStore open(String db) throws StoreException {
        String url = db.startsWith("jdbc:") ? db : "jdbc:sqlite:" + db;
        String shown = url.replaceAll("password=[^&]*", "password=...");
        try {
            Connection c = DriverManager.getConnection(url);
            boolean sqlite = url.startsWith("jdbc:sqlite:");
            if (sqlite) {
                try (Statement s = c.createStatement()) {
                    // WAL with NORMAL sync: a commit survives the process being killed (kill -9); busy_timeout for a second reader.
                    s.execute("PRAGMA journal_mode=WAL");
                    s.execute("PRAGMA synchronous=NORMAL");
                    s.execute("PRAGMA busy_timeout=5000");
                }
            }
            createSchema(c, shown);
            c.setAutoCommit(false);
            return new GameStore(shown, c);
        } catch (SQLException e) {
            throw new StoreException("cannot open the database " + shown + ": " + firstLine(e.getMessage()), e);
        }
    }

    private static void createSchema(Connection c, String shown) throws SQLException, StoreException {
        try (Statement s = c.createStatement()) {
            s.execute("CREATE TABLE IF NOT EXISTS meta (name VARCHAR(40) PRIMARY KEY, value VARCHAR(200) NOT NULL)");
            s.execute("CREATE TABLE IF NOT EXISTS rooms (code VARCHAR(16) PRIMARY KEY, course VARCHAR(80) NOT NULL,"
                    + " listed INTEGER NOT NULL, stroke_limit INTEGER NOT NULL, seats INTEGER NOT NULL,"
                    + " status VARCHAR(12) NOT NULL, created_ms BIGINT NOT NULL, updated_ms BIGINT NOT NULL, start_save TEXT)");
            s.execute("CREATE TABLE IF NOT EXISTS seats (room VARCHAR(16) NOT NULL, seat INTEGER NOT NULL,"
                    + " name VARCHAR(40) NOT NULL, bot INTEGER NOT NULL, level VARCHAR(64), token_hash VARCHAR(64),"
                    + " gone INTEGER NOT NULL, PRIMARY KEY (room, seat))");
            s.execute("CREATE TABLE IF NOT EXISTS events (room VARCHAR(16) NOT NULL, seq BIGINT NOT NULL, data TEXT NOT NULL,"
                    + " PRIMARY KEY (room, seq))");
            s.execute("CREATE TABLE IF NOT EXISTS scores (board VARCHAR(80) NOT NULL, room VARCHAR(16) NOT NULL,"
                    + " seat INTEGER NOT NULL, name VARCHAR(40) NOT NULL, level VARCHAR(64), strokes INTEGER NOT NULL,"
                    + " par INTEGER NOT NULL, finished_ms BIGINT NOT NULL, PRIMARY KEY (board, room, seat))");
            s.execute("CREATE INDEX IF NOT EXISTS scores_by_board ON scores (board, strokes)");
            s.execute("CREATE INDEX IF NOT EXISTS rooms_by_status ON rooms (status)");
        }
        try (PreparedStatement q = c.prepareStatement("SELECT value FROM meta WHERE name = 'schema'")) {
            ResultSet r = q.executeQuery();
            if (r.next()) {
                if (!String.valueOf(SCHEMA_VERSION).equals(r.getString(1))) {
                    throw new StoreException("the database " + shown + " has schema " + r.getString(1)
                            + "; this server uses schema " + SCHEMA_VERSION, null);
                }
            } else {
                try (PreparedStatement i = c.prepareStatement("INSERT INTO meta (name, value) VALUES ('schema', ?)")) {
                    i.setString(1, String.valueOf(SCHEMA_VERSION));
                    i.executeUpdate();
                }
            }
        }
    }

    /** The database, for messages (a password in the URL is left out). */
    public String description() {
        return description;
    }

    /** Runs {@code work} on the database thread inside a transaction; the future completes after the commit. */
    public <T> CompletableFuture<T> submit(Work<T> work) {
        CompletableFuture<T> done = new CompletableFuture<>();
        if (closed) {
            done.completeExceptionally(new SQLException("the database is closed"));
            return done;
        }
        queue.add(new Task<>(work, done));
        return done;
    }

    /** As {@link #submit}, waiting for the result (start-up, tests). */
    public <T> T call(Work<T> work) throws StoreException {
        try {
            return submit(work).get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new StoreException("interrupted while using the database", e);
        } catch (java.util.concurrent.ExecutionException e) {
            throw new StoreException("database " + description + ": " + firstLine(String.valueOf(e.getCause().getMessage())), e.getCause());
        }
    }

    private void loop() {
        List<Task<?>> batch = new ArrayList<>();
        while (true) {
            try {
                batch.add(queue.take());
            } catch (InterruptedException e) {
                return;
            }
            queue.drainTo(batch, MAX_BATCH - 1);
            if (batch.get(0).work() == null) return; // the close marker
            runBatch(batch);
            batch.clear();
        }
    }

    private void runBatch(List<Task<?>> batch) {
        List<Object> results = new ArrayList<>();
        boolean stop = false;
        try {
            for (Task<?> t : batch) {
                if (t.work() == null) {
                    stop = true;
                    break;
                }
                results.add(t.work().run(connection));
            }
            connection.commit();
            for (int i = 0; i < results.size(); i++) complete(batch.get(i), results.get(i));
        } catch (SQLException | RuntimeException e) {
            rollback();
            // One task failed: run them one by one, so that only the failing one fails.
            for (Task<?> t : batch) {
                if (t.work() == null) {
                    stop = true;
                    break;
                }
                try {
                    Object r = t.work().run(connection);
                    connection.commit();
                    complete(t, r);
                } catch (SQLException | RuntimeException e2) {
                    rollback();
                    t.done().completeExceptionally(e2);
                }
            }
        }
        if (stop) Thread.currentThread().interrupt();
    }

    @SuppressWarnings("unchecked")
    private static <T> void complete(Task<T> t, Object result) {
        t.done().complete((T) result);
    }

    private void rollback() {
        try {
            connection.rollback();
        } catch (SQLException ignored) {
            // the connection is broken: the next task reports it
        }
    }

    // ---- what the server stores ----

    public CompletableFuture<Void> createRoom(StoredRoom room) {
        return submit(c -> {
            try (PreparedStatement p = c.prepareStatement("INSERT INTO rooms (code, course, listed, stroke_limit, seats,"
                    + " status, created_ms, updated_ms, start_save) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)")) {
                p.setString(1, room.code());
                p.setString(2, room.course());
                p.setInt(3, room.listed() ? 1 : 0);
                p.setInt(4, room.strokeLimit());
                p.setInt(5, room.seats());
                p.setString(6, room.status());
                p.setLong(7, room.createdMs());
                p.setLong(8, room.createdMs());
                p.setString(9, room.startSave());
                p.executeUpdate();
            }
            for (StoredSeat s : room.seatList()) insertSeat(c, room.code(), s);
            return null;
        });
    }

    public CompletableFuture<Void> addSeat(String room, StoredSeat seat) {
        return submit(c -> {
            insertSeat(c, room, seat);
            return null;
        });
    }

    private static void insertSeat(Connection c, String room, StoredSeat s) throws SQLException {
        try (PreparedStatement p = c.prepareStatement("INSERT INTO seats (room, seat, name, bot, level, token_hash, gone)"
                + " VALUES (?, ?, ?, ?, ?, ?, ?)")) {
            p.setString(1, room);
            p.setInt(2, s.seat());
            p.setString(3, s.name());
            p.setInt(4, s.bot() ? 1 : 0);
            p.setString(5, s.level());
            p.setString(6, s.tokenHash());
            p.setInt(7, s.gone() ? 1 : 0);
            p.executeUpdate();
        }
    }

    /** The room's game began: its round as it starts (a saved round). */
    public CompletableFuture<Void> startRoom(String room, String startSave, long nowMs) {
        return submit(c -> {
            try (PreparedStatement p = c.prepareStatement(
                    "UPDATE rooms SET status = 'playing', start_save = ?, updated_ms = ? WHERE code = ?")) {
                p.setString(1, startSave);
                p.setLong(2, nowMs);
                p.setString(3, room);
                p.executeUpdate();
            }
            return null;
        });
    }

    /**
     * One event of a room, with the scores it completes (a finished hole, a finished round) and the
     * room's status after it, in one transaction: the event is there exactly once, or not at all.
     */
    public CompletableFuture<Void> appendEvent(String room, long seq, String eventJson, List<Score> scores, String status,
                                               long nowMs) {
        return submit(c -> {
            try (PreparedStatement p = c.prepareStatement("INSERT INTO events (room, seq, data) VALUES (?, ?, ?)")) {
                p.setString(1, room);
                p.setLong(2, seq);
                p.setString(3, eventJson);
                p.executeUpdate();
            }
            if (!scores.isEmpty()) {
                try (PreparedStatement p = c.prepareStatement("INSERT INTO scores (board, room, seat, name, level, strokes,"
                        + " par, finished_ms) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")) {
                    for (Score s : scores) {
                        p.setString(1, s.board());
                        p.setString(2, s.room());
                        p.setInt(3, s.seat());
                        p.setString(4, s.name());
                        p.setString(5, s.level());
                        p.setInt(6, s.strokes());
                        p.setInt(7, s.par());
                        p.setLong(8, s.finishedMs());
                        p.addBatch();
                    }
                    p.executeBatch();
                }
            }
            setStatus(c, room, status, nowMs);
            return null;
        });
    }

    public CompletableFuture<Void> setStatus(String room, String status, long nowMs) {
        return submit(c -> {
            setStatus(c, room, status, nowMs);
            return null;
        });
    }

    private static void setStatus(Connection c, String room, String status, long nowMs) throws SQLException {
        try (PreparedStatement p = c.prepareStatement("UPDATE rooms SET status = ?, updated_ms = ? WHERE code = ?")) {
            p.setString(1, status);
            p.setLong(2, nowMs);
            p.setString(3, room);
            p.executeUpdate();
        }
    }

    /** A seat freed in a room's lobby (its player left before the start). */
    public CompletableFuture<Void> removeSeat(String room, int seat) {
        return submit(c -> {
            try (PreparedStatement p = c.prepareStatement("DELETE FROM seats WHERE room = ? AND seat = ?")) {
                p.setString(1, room);
                p.setInt(2, seat);
                p.executeUpdate();
            }
            return null;
        });
    }

    /** The player of the seat left for good. */
    public CompletableFuture<Void> seatGone(String room, int seat) {
        return submit(c -> {
            try (PreparedStatement p = c.prepareStatement("UPDATE seats SET gone = 1 WHERE room = ? AND seat = ?")) {
                p.setString(1, room);
                p.setInt(2, seat);
                p.executeUpdate();
            }
            return null;
        });
    }

    /** Every room with one of these statuses, with its seats and events (a server starting up). */
    public List<StoredRoom> loadRooms(List<String> statuses) throws StoreException {
        return call(c -> {
            Map<String, StoredRoom> rooms = new LinkedHashMap<>();
            String in = String.join(", ", statuses.stream().map(s -> "?").toList());
            try (PreparedStatement p = c.prepareStatement("SELECT code, course, listed, stroke_limit, seats, status, created_ms,"
                    + " start_save FROM rooms WHERE status IN (" + in + ") ORDER BY created_ms, code")) {
                for (int i = 0; i < statuses.size(); i++) p.setString(i + 1, statuses.get(i));
                ResultSet r = p.executeQuery();
                while (r.next()) {
                    rooms.put(r.getString(1), new StoredRoom(r.getString(1), r.getString(2), r.getInt(3) != 0, r.getInt(4),
                            r.getInt(5), r.getString(6), r.getLong(7), r.getString(8), List.of(), List.of()));
                }
            }
            List<StoredRoom> out = new ArrayList<>();
            for (StoredRoom room : rooms.values()) {
                List<StoredSeat> seats = new ArrayList<>();
                try (PreparedStatement p = c.prepareStatement("SELECT seat, name, bot, level, token_hash, gone FROM seats"
                        + " WHERE room = ? ORDER BY seat")) {
                    p.setString(1, room.code());
                    ResultSet r = p.executeQuery();
                    while (r.next()) {
                        seats.add(new StoredSeat(r.getInt(1), r.getString(2), r.getInt(3) != 0, r.getString(4), r.getString(5),
                                r.getInt(6) != 0));
                    }
                }
                List<String> events = new ArrayList<>();
                try (PreparedStatement p = c.prepareStatement("SELECT data FROM events WHERE room = ? ORDER BY seq")) {
                    p.setString(1, room.code());
                    ResultSet r = p.executeQuery();
                    while (r.next()) events.add(r.getString(1));
                }
                out.add(new StoredRoom(room.code(), room.course(), room.listed(), room.strokeLimit(), room.seats(),
                        room.status(), room.createdMs(), room.startSave(), seats, events));
            }
            return out;
        });
    }

    /** The stored events of one room, in order (tests, replays). */
    public List<String> events(String room) throws StoreException {
        return call(c -> {
            List<String> events = new ArrayList<>();
            try (PreparedStatement p = c.prepareStatement("SELECT data FROM events WHERE room = ? ORDER BY seq")) {
                p.setString(1, room);
                ResultSet r = p.executeQuery();
                while (r.next()) events.add(r.getString(1));
            }
            return events;
        });
    }

    /** The best {@code limit} scores on a board: each player's best, fewest strokes first (earlier first among equals). */
    public CompletableFuture<List<Score>> leaderboard(String board, int limit) {
        return submit(c -> {
            List<Score> out = new ArrayList<>();
            try (PreparedStatement p = c.prepareStatement("SELECT board, name, level, strokes, par, room, seat, finished_ms"
                    + " FROM scores s WHERE board = ? AND NOT EXISTS (SELECT 1 FROM scores b WHERE b.board = s.board"
                    + " AND b.name = s.name AND (b.strokes < s.strokes OR (b.strokes = s.strokes AND"
                    + " (b.finished_ms < s.finished_ms OR (b.finished_ms = s.finished_ms AND (b.room < s.room"
                    + " OR (b.room = s.room AND b.seat < s.seat)))))))"
                    + " ORDER BY strokes, finished_ms, room, seat LIMIT ?")) {
                p.setString(1, board);
                p.setInt(2, limit);
                ResultSet r = p.executeQuery();
                while (r.next()) {
                    out.add(new Score(r.getString(1), r.getString(2), r.getString(3), r.getInt(4), r.getInt(5), r.getString(6),
                            r.getInt(7), r.getLong(8)));
                }
            }
            return out;
        });
    }

    /** Waits for the queued work, then closes the connection. */
    @Override
    public void close() {
        if (closed) return;
        closed = true;
        queue.add(new Task<>(null, new CompletableFuture<>()));
        try {
            thread.join(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try {
            connection.close();
        } catch (SQLException ignored) {
            // closing anyway
        }
    }

    static String firstLine(String s) {
        return s == null ? "" : s.lines().findFirst().orElse("");
    }
}
