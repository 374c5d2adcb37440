package minigolf.online.server;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import minigolf.game.Round;
import minigolf.online.Json;
import minigolf.online.Protocol;

/** The messages a room sends (docs/online.md, "Server messages"), built on the room's thread. */
final class RoomMessages {
    private final Room room;

    RoomMessages(Room room) {
        this.room = room;
    }

    /** Everything a client needs to show the room; once started, the round as it started and every event since. */
    String snapshot() {
        ObjectNode o = Json.message("room").put("protocol", Protocol.VERSION).put("room", room.code)
                .put("course", room.entry.name()).put("kind", room.entry.isRound() ? "round" : "course")
                .put("title", room.entry.round().name()).put("listed", room.listed)
                .put("status", room.status().jsonName()).put("strokeLimit", room.strokeLimit)
                .put("seq", room.seq()).put("turn", room.turn());
        ArrayNode holes = o.putArray("holes");
        for (Round.Hole h : room.entry.round().holes()) holes.addObject().put("course", h.course()).put("par", h.par());
        seats(o.putArray("seats"));
        if (room.startSave() != null) {
            // The round as it started and every event since: a client settles them as the server did.
            o.put("start", room.startSave());
            // The room's course clock now, and how long it stands yet (a ball still rolls): clients run it on from here.
            long now = room.now();
            o.put("clock", room.clock().at(now)).put("clockRunsIn", room.clock().holdSeconds(now));
            ArrayNode events = o.putArray("events");
            for (String e : room.events()) events.addRawValue(new com.fasterxml.jackson.databind.util.RawValue(e));
        }
        return Json.write(o);
    }

    /** Who sits where, who is connected, whose turn is passed over, and whose turn it is. */
    String seats() {
        ObjectNode o = Json.message("seats").put("seq", room.seq()).put("turn", room.turn());
        seats(o.putArray("seats"));
        return Json.write(o);
    }

    private void seats(ArrayNode out) {
        for (Seat s : room.seats()) {
            ObjectNode o = out.addObject();
            if (!s.isTaken()) {
                o.put("free", true);
                continue;
            }
            o.put("name", s.name).put("bot", s.bot);
            if (s.level != null) o.put("level", s.level);
            o.put("connected", s.bot || s.client != null).put("gone", s.gone);
            o.put("passedOver", room.round() != null && room.round().game().isPassedOver(s.index));
        }
    }

    /** The seat a client now holds; the token only when the seat is new (a resumed seat keeps its token). */
    String joined(int seat, String token) {
        ObjectNode o = Json.message("joined").put("protocol", Protocol.VERSION).put("room", room.code).put("seat", seat)
                .put("name", room.seats()[seat].name);
        if (token != null) o.put("token", token);
        return Json.write(o);
    }

    String notice(String text) {
        return Json.write(Json.message("notice").put("text", text));
    }

    String chat(int seat, String text) {
        return Json.write(Json.message("chat").put("seat", seat).put("name", room.seats()[seat].name).put("text", text));
    }

    String error(String code, String message) {
        return error(code, message, room.seq());
    }

    static String error(String code, String message, long seq) {
        ObjectNode o = Json.message("error").put("code", code).put("message", message);
        if (seq >= 0) o.put("seq", seq);
        return Json.write(o);
    }
}
