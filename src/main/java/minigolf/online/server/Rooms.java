package minigolf.online.server;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import minigolf.game.BotCatalog;
import minigolf.game.Player;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.online.ClientMessage;
import minigolf.online.Json;
import minigolf.online.ProtocolException;
import minigolf.online.store.StoreException;
import minigolf.online.store.StoredRoom;
import minigolf.online.store.StoredSeat;

/** The server's rooms by code: creating them, finding them, and restoring them from the database at start-up. */
final class Rooms {
    /** Finished rooms stay on the web page this long before they are dropped from memory (they stay in the database). */
    static final long FINISHED_KEPT_MS = 60 * 60 * 1000L;

    private final Map<String, Room> rooms = new ConcurrentHashMap<>();
    private final CourseCatalog catalog;
    private final RoomServices svc;

    Rooms(CourseCatalog catalog, RoomServices svc) {
        this.catalog = catalog;
        this.svc = svc;
    }

    Room get(String code) {
        return rooms.get(code);
    }

    Collection<Room> all() {
        return rooms.values();
    }

    /** Opens a room for the client, which takes seat 0; the bots take the last seats. */
    void create(Client c, ClientMessage.Create m) {
        CourseCatalog.Entry entry = catalog.get(m.course());
        if (entry == null) {
            c.seated(null, -1);
            c.send(RoomMessages.error("no-course", "this server has no course or round named " + Json.shown(m.course()), -1));
            return;
        }
        List<String> levels = BotCatalog.names();
        for (String b : m.bots()) {
            if (!levels.contains(b)) {
                c.seated(null, -1);
                c.send(RoomMessages.error("bad-field", "bots: no bot level named " + Json.shown(b) + " (known: "
                        + String.join(", ", levels) + ")", -1));
                return;
            }
        }
        long open = rooms.values().stream()
                .filter(r -> c.address().equals(r.creatorAddress) && !r.view().status().equals("finished")).count();
        if (open >= svc.options().openRoomsPerAddress()) {
            c.seated(null, -1);
            c.send(RoomMessages.error("limit", "this address already has " + open + " open rooms (the limit)", -1));
            return;
        }
        if (rooms.size() >= svc.options().maxRooms()) {
            c.seated(null, -1);
            c.send(RoomMessages.error("limit", "the server is full (" + rooms.size() + " rooms)", -1));
            return;
        }
        Seat[] seats = new Seat[m.seats()];
        String token = Secrets.token();
        seats[0] = new Seat(0, m.name(), false, null, Secrets.hash(token));
        for (int i = 1; i < m.seats(); i++) seats[i] = new Seat(i, null, false, null, null);
        int firstBot = m.seats() - m.bots().size();
        for (int k = 0; k < m.bots().size(); k++) {
            String level = m.bots().get(k);
            seats[firstBot + k] = new Seat(firstBot + k, botName(level, seats), true, level, null);
        }
        String code;
        Room room;
        do {
            code = Secrets.roomCode();
            room = new Room(code, entry, m.listed(), m.strokeLimit(), svc.now(), c.address(), seats, svc);
        } while (rooms.putIfAbsent(code, room) != null);
        Room created = room;
        seats[0].client = c;
        c.seated(created, 0);
        List<StoredSeat> stored = new ArrayList<>();
        for (Seat s : seats) if (s.isTaken()) stored.add(s.stored());
        svc.store().createRoom(new StoredRoom(code, entry.name(), m.listed(), m.strokeLimit(), m.seats(), "lobby",
                created.createdMs, null, stored, List.of())).whenComplete((v, err) -> created.actor.execute(() -> {
            if (err != null) {
                svc.log("room " + created.code + " not stored: " + err.getMessage());
                rooms.remove(created.code);
                c.seated(null, -1);
                c.send(RoomMessages.error("server", "the server could not store the room; try again", -1));
                return;
            }
            svc.log("room " + created.code + " opened on " + entry.name() + " (" + m.seats() + " seats)");
            created.welcome(c, 0, token);
            if (firstBot == 1) created.start();
        }));
    }

    private static String botName(String level, Seat[] seats) {
        String base = Character.toUpperCase(level.charAt(0)) + level.substring(1).toLowerCase(Locale.ROOT) + " bot";
        if (base.length() > Player.MAX_NAME_LENGTH - 2) base = base.substring(0, Player.MAX_NAME_LENGTH - 2);
        String name = base;
        for (int k = 2; taken(name, seats); k++) name = base + " " + k;
        return name;
    }

    private static boolean taken(String name, Seat[] seats) {
        for (Seat s : seats) if (s != null && name.equals(s.name)) return true;
        return false;
    }

    /** Every room in the lobby or in play, from the database, as it was stored; returns how many. */
    int restore() throws StoreException {
        int n = 0;
        for (StoredRoom r : svc.store().loadRooms(List.of("lobby", "playing"))) {
            try {
                Room room = restoreRoom(r);
                rooms.put(r.code(), room);
                n++;
            } catch (ProtocolException | SaveGameException | RuntimeException e) {
                svc.log("room " + r.code() + " not restored: " + e.getMessage());
            }
        }
        return n;
    }

    private Room restoreRoom(StoredRoom r) throws ProtocolException, SaveGameException {
        Seat[] seats = new Seat[r.seats()];
        for (int i = 0; i < seats.length; i++) seats[i] = new Seat(i, null, false, null, null);
        for (StoredSeat s : r.seatList()) {
            Seat seat = new Seat(s.seat(), s.name(), s.bot(), s.level(), s.tokenHash());
            seat.gone = s.gone();
            seats[s.seat()] = seat;
        }
        RoundGame started = r.startSave() == null ? null : minigolf.online.StartSaves.read(r.startSave(), "room " + r.code());
        CourseCatalog.Entry entry;
        if (started != null) {
            CourseCatalog.Entry now = catalog.get(r.course());
            entry = new CourseCatalog.Entry(r.course(), now != null ? now.isRound() : started.round().size() > 1, started.round());
        } else {
            entry = catalog.get(r.course());
            if (entry == null) throw new IllegalStateException("its course " + r.course() + " is no longer offered");
        }
        Room room = new Room(r.code(), entry, r.listed(), r.strokeLimit(), r.createdMs(), null, seats, svc);
        room.restore(started == null ? Room.Status.LOBBY : Room.Status.PLAYING, r.startSave(), started, r.events());
        return room;
    }

    /** Drops rooms finished more than {@link #FINISHED_KEPT_MS} ago from memory. */
    void sweep() {
        long now = System.currentTimeMillis();
        rooms.values().removeIf(r -> r.view().status().equals("finished") && now - r.view().updatedMs() > FINISHED_KEPT_MS);
    }
}
