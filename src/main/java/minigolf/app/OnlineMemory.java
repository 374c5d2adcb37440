package minigolf.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import minigolf.io.AtomicFile;
import minigolf.online.Json;
import minigolf.online.Protocol;

/**
 * What the "Play online" screen remembers between runs ({@code online.json} beside the settings):
 * the server and name last used, and the seat last held with its token, so that a game that
 * crashed or was closed resumes its seat. A file that does not read is as no file.
 */
record OnlineMemory(String server, String name, String room, String token) {
    static final OnlineMemory NONE = new OnlineMemory("127.0.0.1:7777", "Player", null, null);

    static Path file(Path configDir) {
        return configDir.resolve("online.json");
    }

    static OnlineMemory load(Path file) {
        try {
            var o = Json.parse(Files.readString(file, StandardCharsets.UTF_8));
            String room = o.path("room").asText(null), token = o.path("token").asText(null);
            boolean seat = room != null && token != null && Protocol.CODE.matcher(room).matches() && Protocol.TOKEN.matcher(token).matches();
            return new OnlineMemory(o.path("server").asText(NONE.server()), o.path("name").asText(NONE.name()),
                    seat ? room : null, seat ? token : null);
        } catch (IOException | minigolf.online.ProtocolException | RuntimeException e) {
            return NONE;
        }
    }

    void save(Path file) {
        var o = Json.object().put("server", server).put("name", name);
        if (room != null && token != null) o.put("room", room).put("token", token);
        try {
            Files.createDirectories(file.getParent());
            AtomicFile.write(file, Json.write(o).getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            // Not remembered: the seat can still be resumed by this run.
        }
    }

    /** The seat {@code r} with token {@code t} taken on {@code entry}'s server under its name. */
    static OnlineMemory seat(OnlinePlay.Entry entry, String r, String t) {
        return new OnlineMemory(serverText(entry.server()), entry.name(), r, t);
    }

    /** A server's address as typed: {@code HOST:PORT} for a plain WebSocket on the game's path, else the whole URI. */
    static String serverText(java.net.URI uri) {
        boolean plain = "ws".equals(uri.getScheme()) && Protocol.PATH.equals(uri.getPath()) && uri.getPort() > 0;
        return plain ? uri.getHost() + ":" + uri.getPort() : uri.toString();
    }
}
