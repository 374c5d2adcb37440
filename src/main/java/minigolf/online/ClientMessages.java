package minigolf.online;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.Player;

/** Reads a client's message, checking every field (the server trusts nothing), and writes one (the clients). */
public final class ClientMessages {
    private ClientMessages() {
    }

    /** The message in {@code text}; anything else is a {@link ProtocolException} with its error code. */
    public static ClientMessage parse(String text) throws ProtocolException {
        if (text.length() > Protocol.MAX_MESSAGE_BYTES
                || text.getBytes(StandardCharsets.UTF_8).length > Protocol.MAX_MESSAGE_BYTES) {
            throw new ProtocolException("too-large", "messages have at most " + Protocol.MAX_MESSAGE_BYTES + " bytes");
        }
        ObjectNode m = Json.parse(text);
        JsonNode type = m.get("type");
        if (type == null || !type.isTextual()) throw Json.bad("type", "is missing (every message names its type)");
        switch (type.textValue()) {
            case "create": {
                Json.onlyFields(m, List.of("type", "protocol", "name", "course", "seats", "bots", "listed", "strokeLimit"));
                version(m);
                int seats = (int) Json.integer(m, "seats", 1, Protocol.MAX_SEATS);
                List<String> bots = new ArrayList<>();
                JsonNode b = m.get("bots");
                if (b != null && !b.isNull()) {
                    if (!b.isArray() || b.size() > seats - 1) throw Json.bad("bots", "must be a list of at most seats - 1 bot levels");
                    for (int i = 0; i < b.size(); i++) {
                        if (!b.get(i).isTextual() || !Protocol.COURSE_NAME.matcher(b.get(i).textValue()).matches()) {
                            throw Json.bad("bots[" + i + "]", "must be a bot level's name");
                        }
                        bots.add(b.get(i).textValue());
                    }
                }
                boolean listed = !m.has("listed") || Json.bool(m, "listed");
                int limit = m.has("strokeLimit") ? (int) Json.integer(m, "strokeLimit", 1, Game.MAX_STROKE_LIMIT)
                        : Game.DEFAULT_STROKE_LIMIT;
                return new ClientMessage.Create(name(m), Json.matching(m, "course", Protocol.COURSE_NAME,
                        "a course or round name (letters, digits, . _ -)"), seats, bots, listed, limit);
            }
            case "join":
                Json.onlyFields(m, List.of("type", "protocol", "room", "name"));
                version(m);
                return new ClientMessage.Join(room(m), name(m));
            case "resume":
                Json.onlyFields(m, List.of("type", "protocol", "room", "token"));
                version(m);
                return new ClientMessage.Resume(room(m), Json.matching(m, "token", Protocol.TOKEN, "a seat token"));
            case "shot": {
                Json.onlyFields(m, List.of("type", "seq", "velocity", "loft", "wait"));
                long seq = Json.integer(m, "seq", 0, Long.MAX_VALUE);
                double[] v = Json.numbers(m, "velocity", 2);
                double loft = m.has("loft") ? Json.number(m, "loft", 0, Loft.MAX_DEGREES) : 0;
                double wait = m.has("wait") ? Json.number(m, "wait", 0, Protocol.MAX_WAIT_SECONDS) : 0;
                return new ClientMessage.Shot(seq, v[0], v[1], loft, wait);
            }
            case "chat": {
                Json.onlyFields(m, List.of("type", "text"));
                String t = Json.text(m, "text", Protocol.MAX_CHAT_CHARS).strip();
                if (t.isEmpty()) throw Json.bad("text", "is empty");
                return new ClientMessage.Chat(t);
            }
            case "leave":
                Json.onlyFields(m, List.of("type"));
                return new ClientMessage.Leave();
            case "ping":
                Json.onlyFields(m, List.of("type"));
                return new ClientMessage.Ping();
            case "sync":
                Json.onlyFields(m, List.of("type"));
                return new ClientMessage.Sync();
            default:
                throw new ProtocolException("bad-message", "unknown message type " + Json.shown(type.textValue()));
        }
    }

    private static void version(JsonNode m) throws ProtocolException {
        long v = Json.integer(m, "protocol", 0, Integer.MAX_VALUE);
        if (v != Protocol.VERSION) {
            throw new ProtocolException("version", "this server speaks protocol " + Protocol.VERSION + ", the client " + v);
        }
    }

    private static String room(JsonNode m) throws ProtocolException {
        return Json.matching(m, "room", Protocol.CODE, "a room code of " + Protocol.CODE_LENGTH + " letters and digits");
    }

    private static String name(JsonNode m) throws ProtocolException {
        String n = Json.text(m, "name", Player.MAX_NAME_LENGTH).strip();
        if (n.isEmpty()) throw Json.bad("name", "is empty");
        return n;
    }

    /** The JSON text of a message, as a client sends it. */
    public static String write(ClientMessage message) {
        ObjectNode o;
        if (message instanceof ClientMessage.Create c) {
            o = Json.message("create").put("protocol", Protocol.VERSION).put("name", c.name()).put("course", c.course())
                    .put("seats", c.seats()).put("listed", c.listed()).put("strokeLimit", c.strokeLimit());
            ArrayNode bots = o.putArray("bots");
            c.bots().forEach(bots::add);
        } else if (message instanceof ClientMessage.Join j) {
            o = Json.message("join").put("protocol", Protocol.VERSION).put("room", j.room()).put("name", j.name());
        } else if (message instanceof ClientMessage.Resume r) {
            o = Json.message("resume").put("protocol", Protocol.VERSION).put("room", r.room()).put("token", r.token());
        } else if (message instanceof ClientMessage.Shot s) {
            o = Json.message("shot").put("seq", s.seq()).put("loft", s.loft()).put("wait", s.waitSeconds());
            o.putArray("velocity").add(s.vx()).add(s.vy());
        } else if (message instanceof ClientMessage.Chat c) {
            o = Json.message("chat").put("text", c.text());
        } else if (message instanceof ClientMessage.Leave) {
            o = Json.message("leave");
        } else if (message instanceof ClientMessage.Sync) {
            o = Json.message("sync");
        } else {
            o = Json.message("ping");
        }
        return Json.write(o);
    }
}
