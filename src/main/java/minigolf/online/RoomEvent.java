package minigolf.online;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import minigolf.game.PlayerState;
import minigolf.game.PlayerStatus;
import minigolf.game.ShotRecord;
import minigolf.physics.Outcome;

/**
 * One thing that changed the score in an online room: a stroke as the server played it, or a seat
 * picked up without one ({@code stroke} null). {@code after} is the seat's ball and count as the
 * server left them, so a client (or the server itself, restarting from its database) settles
 * exactly there. {@code seq} counts the room's events from 1. {@code clockAfter} is the room's course
 * clock once the stroke has run (s; the stroke's own clock is when it started): clients do not
 * simulate, so this is how they know where moving obstacles stand.
 */
public record RoomEvent(long seq, int hole, int seat, ShotRecord stroke, PlayerState after, double waitSeconds, double clockAfter) {
    private static final List<String> FIELDS = List.of("type", "seq", "hole", "seat", "start", "velocity", "wait",
            "outcome", "end", "ball", "strokes", "penalties", "status", "turn", "clock", "clockAfter");

    /** An event whose clock after is the stroke's own (a pick-up, or a course where the clock does not matter). */
    public RoomEvent(long seq, int hole, int seat, ShotRecord stroke, PlayerState after, double waitSeconds) {
        this(seq, hole, seat, stroke, after, waitSeconds, stroke == null ? 0 : stroke.clock());
    }

    public RoomEvent {
        if (seq < 1) throw new IllegalArgumentException("events count from 1, got " + seq);
        if (after == null) throw new IllegalArgumentException("an event needs the seat's state after it");
        if (stroke != null && stroke.player() != seat) throw new IllegalArgumentException("the stroke is another seat's");
    }

    public boolean isPickUp() {
        return stroke == null;
    }

    /** The message the server sends for it ({@code stroke} or {@code pickup}), with the seat whose turn comes next. */
    public ObjectNode toJson(int turn) {
        ObjectNode o = Json.message(isPickUp() ? "pickup" : "stroke").put("seq", seq).put("hole", hole).put("seat", seat);
        if (stroke != null) {
            o.putArray("start").add(stroke.startX()).add(stroke.startY());
            o.putArray("velocity").add(stroke.vx()).add(stroke.vy()).add(stroke.vz());
            o.put("wait", waitSeconds);
            o.put("outcome", stroke.outcome().jsonName());
            o.putArray("end").add(stroke.endX()).add(stroke.endY());
            // The course clock the stroke was played at (moving obstacles: docs/course-format.md); 0 is left out.
            if (stroke.clock() != 0) o.put("clock", stroke.clock());
            if (clockAfter != 0) o.put("clockAfter", clockAfter);
        }
        o.putArray("ball").add(after.x()).add(after.y());
        o.put("strokes", after.strokes()).put("penalties", after.penalties()).put("status", after.status().jsonName());
        o.put("turn", turn);
        return o;
    }

    /** Reads what {@link #toJson} wrote (from the server or the database), for a room of {@code seats} seats. */
    public static RoomEvent parse(JsonNode o, int seats) throws ProtocolException {
        Json.onlyFields(o, FIELDS);
        String type = Json.text(o, "type", 10);
        long seq = Json.integer(o, "seq", 1, Long.MAX_VALUE);
        int hole = (int) Json.integer(o, "hole", 0, minigolf.game.Round.MAX_HOLES - 1);
        int seat = (int) Json.integer(o, "seat", 0, seats - 1);
        double[] ball = Json.numbers(o, "ball", 2);
        int strokes = (int) Json.integer(o, "strokes", 0, 10_000);
        int penalties = (int) Json.integer(o, "penalties", 0, strokes);
        PlayerStatus status = PlayerStatus.fromJsonName(Json.text(o, "status", 20));
        if (status == null) throw Json.bad("status", "must be playing, holed or picked-up");
        PlayerState after = new PlayerState(ball[0], ball[1], strokes, penalties, status);
        if (type.equals("pickup")) return new RoomEvent(seq, hole, seat, null, after, 0);
        if (!type.equals("stroke")) throw Json.bad("type", "must be stroke or pickup");
        double[] start = Json.numbers(o, "start", 2), v = Json.numbers(o, "velocity", 3), end = Json.numbers(o, "end", 2);
        String outcomeName = Json.text(o, "outcome", 20);
        Outcome outcome = null;
        for (Outcome c : Outcome.values()) if (c.jsonName().equals(outcomeName)) outcome = c;
        if (outcome == null) throw Json.bad("outcome", "unknown outcome " + Json.shown(outcomeName));
        double wait = Json.number(o, "wait", 0, Protocol.MAX_WAIT_SECONDS);
        double clock = o.has("clock") ? Json.number(o, "clock", 0, Double.MAX_VALUE) : 0;
        double clockAfter = o.has("clockAfter") ? Json.number(o, "clockAfter", clock, Double.MAX_VALUE) : 0;
        return new RoomEvent(seq, hole, seat, new ShotRecord(seat, start[0], start[1], v[0], v[1], v[2], outcome, end[0], end[1],
                clock), after, wait, clockAfter);
    }
}
