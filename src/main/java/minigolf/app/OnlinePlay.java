package minigolf.app;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Consumer;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.RoundGame;
import minigolf.online.ClientMessage;
import minigolf.online.RoomEvent;
import minigolf.online.RoundSync;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import minigolf.online.client.RoomMirror;

/**
 * A room on a game server as the game window plays it (docs/online.md). The connection's messages
 * queue up on its own thread and are taken in on the render thread ({@link #poll()}); the room's
 * state is a {@link RoomMirror}. The window shows the round a step behind the mirror: each stroke
 * the server sends is animated with the game's engine from its start and velocity, then settled
 * where the server put the ball ({@link #settle}). A dropped connection is retried and the seat
 * resumed with its token; everything that happens is said in one line.
 */
final class OnlinePlay {
    /** How the room is entered. */
    record Entry(URI server, String name, String create, int seats, List<String> bots, boolean listed, String room,
                 String token) {
    }

    private record Connected(OnlineClient client) {
    }

    private record Failed(String reason) {
    }

    private record Closed(OnlineClient client, String reason) {
    }

    /** A message and when it arrived (RoomMirror.nowMs: the room's clock is reckoned from it). */
    private record Arrived(ObjectNode message, long atMs) {
    }

    /** Lines of chat and notices kept for the panel. */
    static final int CHAT_LINES = 8;
    /** Retries of a lost connection: 0.5 s, doubling to 8 s, for at most this long. */
    static final Duration RECONNECT_FOR = Duration.ofMinutes(5);

    private final Entry entry;
    private final Consumer<String> say;
    private final java.util.function.BiConsumer<String, String> seated;
    private final Queue<Object> inbox = new ConcurrentLinkedQueue<>();
    private final RoomMirror mirror = new RoomMirror();
    private final Deque<RoomEvent> toShow = new ArrayDeque<>();
    private final List<String> chat = new ArrayList<>();
    private OnlineClient client;
    private RoundGame shown;
    private boolean resynced;
    private long shotSentAt = -1;
    /** When the shot on its way left (System.nanoTime). */
    private long shotSentNanos;
    /**
     * A shot with no answer at all (no stroke, no refusal) for this long may be played again: it was lost on
     * its way, and the player would otherwise see its turn and never be able to shoot. The server's event
     * count keeps a shot that was only slow from being played twice.
     */
    private long answerWaitNanos = HeadlessPlayer.RESEND_AFTER.toNanos();
    /** The room's events this client has had (shown, or queued to be shown). */
    private long received = -1;
    private String failure;
    private long reconnectStarted = -1;
    private long retryPause = 500;
    private boolean closed;

    /**
     * Connects (on a thread of its own) and enters the room; {@code seated} hears the room's code
     * and the seat's token once a new seat is taken.
     */
    OnlinePlay(Entry entry, Consumer<String> say, java.util.function.BiConsumer<String, String> seated) {
        this.entry = entry;
        this.say = say;
        this.seated = seated;
        say.accept("connecting to " + entry.server().getHost() + ":" + entry.server().getPort() + " ...");
        connect(0);
    }

    /** Pings every connection now and then, so that a quiet room (a paused game) is not closed as idle. */
    private static final java.util.concurrent.ScheduledExecutorService PINGS =
            java.util.concurrent.Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "minigolf-online-ping");
                t.setDaemon(true);
                return t;
            });
    private java.util.concurrent.ScheduledFuture<?> pinging;

    private void connect(long delayMillis) {
        Thread t = new Thread(() -> {
            try {
                if (delayMillis > 0) Thread.sleep(delayMillis);
                OnlineClient[] self = new OnlineClient[1];
                OnlineClient c = OnlineClient.connect(entry.server(), new OnlineClient.Listener() {
                    public void onMessage(ObjectNode message) {
                        inbox.add(new Arrived(message, RoomMirror.nowMs()));
                    }

                    public void onClosed(String reason) {
                        inbox.add(new Closed(self[0], reason));
                    }
                }, Duration.ofSeconds(10));
                self[0] = c;
                inbox.add(new Connected(c));
                synchronized (this) {
                    if (pinging != null) pinging.cancel(false);
                    pinging = PINGS.scheduleAtFixedRate(() -> {
                        if (c.isOpen()) c.send(new ClientMessage.Ping());
                    }, 30, 30, java.util.concurrent.TimeUnit.SECONDS);
                }
            } catch (IOException e) {
                inbox.add(new Failed(e.getMessage()));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "minigolf-online-connect");
        t.setDaemon(true);
        t.start();
    }

    /** Takes in what arrived; call on the render thread once a frame. */
    void poll() {
        for (Object item; (item = inbox.poll()) != null; ) {
            if (closed) {
                if (item instanceof Connected c) c.client().close();
                continue;
            }
            if (item instanceof Connected c) {
                client = c.client();
                reconnectStarted = -1;
                retryPause = 500;
                if (mirror.token() != null || entry.token() != null) {
                    client.send(new ClientMessage.Resume(mirror.room() != null ? mirror.room() : entry.room(),
                            mirror.token() != null ? mirror.token() : entry.token()));
                } else if (entry.create() != null) {
                    client.send(new ClientMessage.Create(entry.name(), entry.create(), entry.seats(), entry.bots(), entry.listed(),
                            Game.DEFAULT_STROKE_LIMIT));
                } else {
                    client.send(new ClientMessage.Join(entry.room(), entry.name()));
                }
            } else if (item instanceof Failed f) {
                lost(f.reason());
            } else if (item instanceof Closed c) {
                if (c.client() == client) {
                    client = null;
                    lost(c.reason());
                }
            } else if (item instanceof Arrived a) {
                take(a.message(), a.atMs());
            }
        }
        if (client != null && shotSentAt >= 0 && shotSentAt == mirror.seq() && mirror.isMyTurn()
                && System.nanoTime() - shotSentNanos >= answerWaitNanos) {
            shotSentAt = -1;
            say.accept(String.format(java.util.Locale.ROOT, "no answer from the server to the shot for %.0f s: play it again",
                    answerWaitNanos / 1e9));
        }
        // Whose turns the server passes over (dropped players), on the hole shown.
        List<RoomMirror.SeatInfo> seats = mirror.seats();
        if (shown != null && !shown.isOver() && seats.size() == shown.game().players().size()) {
            for (int i = 0; i < seats.size(); i++) shown.game().passOver(i, seats.get(i).passedOver());
        }
    }

    private void lost(String reason) {
        if (mirror.token() == null && entry.token() == null) {
            // Never seated: nothing to resume.
            failure = reason;
            say.accept(reason);
            return;
        }
        long now = System.nanoTime();
        if (reconnectStarted < 0) {
            reconnectStarted = now;
            say.accept(reason + "; reconnecting ...");
        }
        if (now - reconnectStarted > RECONNECT_FOR.toNanos()) {
            failure = "the server stayed unreachable for " + RECONNECT_FOR.toMinutes() + " minutes (" + reason
                    + "); the seat is kept: resume it from Play online";
            say.accept(failure);
            return;
        }
        connect(retryPause);
        retryPause = Math.min(8000, retryPause * 2);
    }

    private void take(ObjectNode m, long atMs) {
        RoomMirror.Update u = mirror.apply(m, atMs);
        switch (u.change()) {
            case JOINED -> {
                if (m.hasNonNull("token")) seated.accept(mirror.room(), mirror.token());
            }
            case SNAPSHOT -> {
                // The whole room anew. When it holds nothing this client has not had (the server's card at the
                // end, a resume that missed nothing), the strokes being shown play on; else showing starts from it.
                if (shown == null || mirror.round() == null || mirror.seq() != received) {
                    toShow.clear();
                    shown = mirror.round();
                    resynced = true;
                    shotSentAt = -1;
                }
                received = mirror.seq();
            }
            case EVENT -> {
                toShow.add(u.event());
                received = u.event().seq();
            }
            case OUT_OF_STEP -> {
                if (client != null) client.send(new ClientMessage.Sync());
            }
            case CHAT, NOTICE -> {
                line(u.text());
                say.accept(u.text());
            }
            case ERROR -> {
                if (u.code().equals("stale") && client != null) client.send(new ClientMessage.Sync());
                shotSentAt = -1;
                if (mirror.seat() < 0) failure = u.text();
                say.accept("server: " + u.text());
            }
            default -> {
            }
        }
    }

    private void line(String text) {
        chat.add(text);
        while (chat.size() > CHAT_LINES) chat.remove(0);
    }

    // ---- what the window shows ----

    /** True once after a whole new state came (the window starts showing it afresh). */
    boolean takeResync() {
        boolean r = resynced;
        resynced = false;
        return r;
    }

    /** The round as shown: the server's, less the strokes still to animate. Null before the start. */
    RoundGame shown() {
        return shown;
    }

    /** The next stroke or pick-up to show, or null. */
    RoomEvent nextEvent() {
        if (shown == null || toShow.isEmpty()) return null;
        // The hole it belongs to must be the one shown (a card may be open for the hole before).
        return toShow.peek().hole() == shown.holeIndex() && !shown.isHoleOver() ? toShow.poll() : null;
    }

    /** The shown round after {@code e}, without starting the next hole (the card comes first, as in hot seat). */
    RoundGame settle(RoomEvent e) {
        Game before = shown.game();
        RoundGame after = RoundSync.applyOnly(shown, e);
        for (int i = 0; i < before.players().size(); i++) after.game().passOver(i, before.isPassedOver(i));
        shown = after;
        return shown;
    }

    /** The room's course clock now, as this client reckons it from the server's messages. */
    double roomClock() {
        return mirror.clockAt(RoomMirror.nowMs());
    }

    /** Whether the round shown is on the hole the server is on with nothing left to show (the room's clock is this hole's). */
    boolean caughtUp() {
        return shown != null && mirror.round() != null && toShow.isEmpty() && !shown.isOver() && !mirror.round().isOver()
                && shown.holeIndex() == mirror.round().holeIndex() && !shown.isHoleOver();
    }

    /** How long a shot may go unanswered before it may be played again (tests: a short wait). */
    void answerWait(Duration wait) {
        answerWaitNanos = wait.toNanos();
    }

    /** This seat may shoot now: its turn on the server, everything before it shown, no shot on its way. */
    boolean canShoot() {
        return client != null && mirror.isMyTurn() && toShow.isEmpty() && shotSentAt != mirror.seq() && shown != null
                && shown.game().currentPlayer() == mirror.seat() && !shown.isHoleOver();
    }

    /** Sends a stroke (vx, vy, vz) as the protocol has it: the aim over the ground, its loft, no wait. */
    void shoot(double vx, double vy, double vz) {
        double ground = Math.hypot(vx, vy), speed = Math.sqrt(ground * ground + vz * vz);
        double loft = Math.min(Loft.MAX_DEGREES, Loft.degreesOf(vx, vy, vz));
        double ax = ground > 0 ? vx / ground * speed : 0, ay = ground > 0 ? vy / ground * speed : 0;
        shotSentAt = mirror.seq();
        shotSentNanos = System.nanoTime();
        client.send(new ClientMessage.Shot(mirror.seq(), ax, ay, loft, 0));
    }

    void sendChat(String text) {
        if (client != null && !text.isBlank()) client.send(new ClientMessage.Chat(text.strip()));
    }

    /** Leaves the room for good (the seat picks up from now on). */
    void leave() {
        if (client != null) client.send(new ClientMessage.Leave());
        close();
    }

    /** Closes the connection; the seat is kept on the server for a resume. */
    void close() {
        closed = true;
        synchronized (this) {
            if (pinging != null) pinging.cancel(false);
        }
        if (client != null) client.close();
        client = null;
    }

    RoomMirror mirror() {
        return mirror;
    }

    List<String> chat() {
        return chat;
    }

    /** Why the room could not be entered or kept (one line), or null. */
    String failure() {
        return failure;
    }

    boolean connected() {
        return client != null && client.isOpen();
    }

    Entry entry() {
        return entry;
    }
}
