package minigolf.online.client;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.online.StartSaves;
import minigolf.online.ProtocolException;
import minigolf.online.RoomClock;
import minigolf.online.RoomEvent;
import minigolf.online.RoundSync;

/**
 * A client's copy of a room, kept up to date from the server's messages: the seat it holds, who
 * sits where, whose turn it is, and the round itself as a {@link RoundGame} (so the game shows it
 * with hot seat's HUD and round card, and saves it as hot seat does). Strokes are settled where the
 * server says ({@link RoundSync}); an event that does not follow the last one asks for a resync.
 * The room's course clock is reckoned from each message and the moment it arrived ({@link #clockAt}).
 * Not thread-safe: one thread applies the messages.
 */
public final class RoomMirror {
    /** A seat as the server describes it. */
    public record SeatInfo(String name, boolean bot, String level, boolean connected, boolean gone, boolean passedOver,
                           boolean free) {
    }

    /** What a message changed. */
    public enum Change {
        /** This client holds a seat now (its token, if new, in {@link #token()}). */
        JOINED,
        /** The whole room was replaced (joined, resynced, the round started or finished). */
        SNAPSHOT,
        /** A stroke or pick-up was settled: {@link Update#event()}. */
        EVENT,
        SEATS,
        CHAT,
        NOTICE,
        /** The server refused something: {@link Update#code()} and {@link Update#text()}. */
        ERROR,
        /** An event was missed: the client should send {@code sync}. */
        OUT_OF_STEP,
        /** Nothing this client uses (a pong, an old event). */
        NONE
    }

    public record Update(Change change, RoomEvent event, String code, String text) {
    }

    private String room;
    private int seat = -1;
    private String token;
    private String status = "lobby";
    private String course;
    private String title;
    private boolean isRound;
    private long seq;
    private int turn = -1;
    private List<SeatInfo> seats = List.of();
    private RoundGame round;
    private RoomClock clock = RoomClock.startingAt(0);
    private long receivedMs;

    /** Applies a message that arrives now. */
    public Update apply(ObjectNode m) {
        return apply(m, nowMs());
    }

    /** Applies a message that arrived at {@code receivedMs} (of {@link #nowMs()}'s clock). */
    public Update apply(ObjectNode m, long receivedMs) {
        this.receivedMs = receivedMs;
        String type = m.path("type").asText("");
        try {
            switch (type) {
                case "joined":
                    room = m.path("room").asText();
                    seat = m.path("seat").asInt(-1);
                    if (m.hasNonNull("token")) token = m.get("token").asText();
                    return new Update(Change.JOINED, null, null, null);
                case "room":
                    snapshot(m);
                    return new Update(Change.SNAPSHOT, null, null, null);
                case "stroke":
                case "pickup":
                    return event(m);
                case "seats":
                    seats(m);
                    return new Update(Change.SEATS, null, null, null);
                case "chat":
                    return new Update(Change.CHAT, null, null, m.path("name").asText("?") + ": " + m.path("text").asText(""));
                case "notice":
                    return new Update(Change.NOTICE, null, null, m.path("text").asText(""));
                case "error":
                    return new Update(Change.ERROR, null, m.path("code").asText("error"), m.path("message").asText(""));
                default:
                    return new Update(Change.NONE, null, null, null);
            }
        } catch (ProtocolException | SaveGameException | RuntimeException e) {
            // A message that does not fit what we hold: start again from the server's whole state.
            return new Update(Change.OUT_OF_STEP, null, null, e.getMessage());
        }
    }

    private void snapshot(ObjectNode m) throws SaveGameException, ProtocolException {
        room = m.path("room").asText(room);
        status = m.path("status").asText("lobby");
        course = m.path("course").asText("");
        title = m.path("title").asText(course);
        isRound = "round".equals(m.path("kind").asText());
        JsonNode start = m.get("start");
        round = start == null || start.isNull() ? null : StartSaves.read(start.asText(), "the server's room " + room);
        seq = 0;
        int n = Math.max(1, m.path("seats").size());
        for (JsonNode e : m.path("events")) {
            RoomEvent event = RoomEvent.parse(e, n);
            if (event.seq() != seq + 1) throw new ProtocolException("bad-message", "event " + event.seq() + " follows " + seq);
            round = RoundSync.apply(round, event);
            seq = event.seq();
        }
        if (seq != m.path("seq").asLong(0)) throw new ProtocolException("bad-message", "the room's events end at " + seq);
        clock = RoomClock.received(m.path("clock").asDouble(0), m.path("clockRunsIn").asDouble(0), receivedMs);
        seats(m);
    }

    private Update event(ObjectNode m) throws ProtocolException {
        RoomEvent e = RoomEvent.parse(m, Math.max(1, seats.size()));
        if (e.seq() <= seq) return new Update(Change.NONE, null, null, null);
        if (e.seq() != seq + 1 || round == null) return new Update(Change.OUT_OF_STEP, null, null, "missed events before " + e.seq());
        int hole = round.holeIndex();
        round = RoundSync.apply(round, e);
        boolean holeEnded = round.isOver() || round.holeIndex() != hole;
        // The server hit the stroke its wait after the shot reached it; here the wait runs from the event's arrival.
        clock = e.isPickUp() ? clock.afterPickUp(receivedMs, holeEnded)
                : RoomClock.afterStroke(e.stroke().clock(), e.clockAfter(), receivedMs + Math.round(e.waitSeconds() * 1000), holeEnded);
        seq = e.seq();
        turn = m.path("turn").asInt(-1);
        if (round.isOver()) status = "finished";
        applyPassOver();
        return new Update(Change.EVENT, e, null, null);
    }

    private void seats(ObjectNode m) {
        List<SeatInfo> list = new ArrayList<>();
        for (JsonNode s : m.path("seats")) {
            list.add(new SeatInfo(s.path("name").asText(null), s.path("bot").asBoolean(), s.path("level").asText(null),
                    s.path("connected").asBoolean(), s.path("gone").asBoolean(), s.path("passedOver").asBoolean(),
                    s.path("free").asBoolean()));
        }
        seats = List.copyOf(list);
        if (m.has("turn") && m.path("seq").asLong(-1) == seq) turn = m.get("turn").asInt(-1);
        applyPassOver();
    }

    private void applyPassOver() {
        if (round == null || round.isOver() || round.game().players().size() != seats.size()) return;
        for (int i = 0; i < seats.size(); i++) round.game().passOver(i, seats.get(i).passedOver());
    }

    public String room() {
        return room;
    }

    public int seat() {
        return seat;
    }

    public String token() {
        return token;
    }

    /** lobby, playing or finished. */
    public String status() {
        return status;
    }

    public String course() {
        return course;
    }

    public String title() {
        return title;
    }

    public boolean isRound() {
        return isRound;
    }

    public long seq() {
        return seq;
    }

    /** Whose turn the server says it is (-1 outside play). */
    public int turn() {
        return turn;
    }

    public List<SeatInfo> seats() {
        return seats;
    }

    /** The round as settled so far; null before it starts. */
    public RoundGame round() {
        return round;
    }

    /** The room's course clock at {@code nowMs} as this client reckons it (the server's, behind by the message's travel). */
    public double clockAt(long nowMs) {
        return clock.at(nowMs);
    }

    /** The milliseconds {@link #apply(ObjectNode, long)} and {@link #clockAt} count in: a monotonic clock of this process. */
    public static long nowMs() {
        return System.nanoTime() / 1_000_000;
    }

    public boolean isMyTurn() {
        return "playing".equals(status) && seat >= 0 && turn == seat && round != null && !round.isOver();
    }
}
