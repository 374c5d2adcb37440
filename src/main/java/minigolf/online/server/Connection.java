package minigolf.online.server;

import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import minigolf.online.ClientMessage;
import minigolf.online.ClientMessages;
import minigolf.online.Json;
import minigolf.online.ProtocolException;

/**
 * One WebSocket connection: it reads each message within the size and rate limits, checks it
 * ({@link ClientMessages}) and hands it to its room. A bad message gets an {@code error} reply and is
 * dropped; nothing a client sends reaches a room unchecked. Public only because Jetty calls it by reflection.
 */
public final class Connection implements Session.Listener.AutoDemanding, Client {
    /** After this many messages in a row over the rate limit, the connection is closed (a flood). */
    static final int FLOOD_CLOSE = 1000;

    private final Rooms rooms;
    private final String address;
    private final RateLimiter limiter;
    private final Runnable onClose;
    private volatile Session session;
    private volatile Room room;
    private volatile int seat = -1;
    /** Set when a create, join or resume is sent to a room, cleared if it fails: one seat per connection. */
    private volatile boolean claimed;
    private long lastLimitReplyNanos;
    private int droppedInARow;

    Connection(Rooms rooms, String address, ServerOptions options, Runnable onClose) {
        this.rooms = rooms;
        this.address = address;
        this.limiter = new RateLimiter(options.messagesPerSecond(), options.messageBurst(), System.nanoTime());
        this.onClose = onClose;
    }

    @Override
    public void onWebSocketOpen(Session s) {
        session = s;
    }

    @Override
    public void onWebSocketText(String text) {
        long now = System.nanoTime();
        if (!limiter.tryAcquire(now)) {
            if (++droppedInARow >= FLOOD_CLOSE) {
                close(1008, "too many messages");
            } else if (now - lastLimitReplyNanos > 1_000_000_000L) {
                lastLimitReplyNanos = now;
                send(RoomMessages.error("rate-limited", "too many messages: they are dropped (the limit is in docs/online.md)", -1));
            }
            return;
        }
        droppedInARow = 0;
        ClientMessage m;
        try {
            m = ClientMessages.parse(text);
        } catch (ProtocolException e) {
            send(RoomMessages.error(e.code(), e.getMessage(), -1));
            return;
        }
        Room r = room;
        if (m instanceof ClientMessage.Ping) {
            send(Json.write(Json.message("pong")));
        } else if (m instanceof ClientMessage.Sync && r != null) {
            r.sync(this, seat);
        } else if (m instanceof ClientMessage.Create || m instanceof ClientMessage.Join || m instanceof ClientMessage.Resume) {
            if (claimed) {
                send(RoomMessages.error("already-seated", "this connection already holds (or is taking) a seat", -1));
                return;
            }
            claimed = true;
            if (m instanceof ClientMessage.Create c) {
                rooms.create(this, c);
            } else {
                String code = m instanceof ClientMessage.Join j ? j.room() : ((ClientMessage.Resume) m).room();
                Room target = rooms.get(code);
                if (target == null) {
                    claimed = false;
                    send(RoomMessages.error("no-room", "there is no open room " + code, -1));
                } else if (m instanceof ClientMessage.Join j) {
                    target.join(this, j.name());
                } else {
                    target.resume(this, ((ClientMessage.Resume) m).token());
                }
            }
        } else if (r == null) {
            send(RoomMessages.error("not-seated", "create, join or resume a room first", -1));
        } else {
            r.message(this, seat, m);
        }
    }

    @Override
    public void onWebSocketClose(int statusCode, String reason, Callback callback) {
        Room r = room;
        if (r != null) r.disconnected(this, seat);
        onClose.run();
        callback.succeed();
    }

    @Override
    public void onWebSocketError(Throwable cause) {
        // Jetty closes the session after this; onWebSocketClose does the rest.
    }

    @Override
    public void send(String json) {
        Session s = session;
        if (s == null || !s.isOpen()) return;
        // Jetty queues at most the container's maxOutgoingFrames; a client that cannot keep up fails here and is dropped.
        s.sendText(json, Callback.from(() -> { }, failure -> s.disconnect()));
    }

    @Override
    public void close(int code, String reason) {
        Session s = session;
        if (s != null && s.isOpen()) s.close(code, reason, Callback.NOOP);
    }

    @Override
    public void seated(Room r, int index) {
        room = r;
        seat = index;
        claimed = r != null;
    }

    @Override
    public String address() {
        return address;
    }
}
