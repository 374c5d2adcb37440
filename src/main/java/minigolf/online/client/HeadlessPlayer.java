package minigolf.online.client;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import minigolf.game.BotCatalog;
import minigolf.game.BotConditions;
import minigolf.game.BotControl;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.PlayerState;
import minigolf.game.RoundScorecard;
import minigolf.game.ShotPlanner;
import minigolf.io.AtomicFile;
import minigolf.online.ClientMessage;
import minigolf.online.Json;
import minigolf.online.Protocol;
import minigolf.online.ProtocolException;

/**
 * A client without a window that plays one seat with a bot to the end of the round: the
 * {@code minigolf join} command and the load benchmark's simulated players. It creates a room (and
 * reports its code), joins one, or resumes a seat from its seat file; a dropped connection is
 * reconnected and the seat resumed with its token. Everything happens on the thread that calls
 * {@link #run()}.
 */
public final class HeadlessPlayer {
    /**
     * What to do. Exactly one of {@code create} (a course or round name) and {@code room} is given,
     * unless {@code seatFile} already holds a seat, which is then resumed.
     *
     * @param thinkMillis a pause before each shot (the benchmark's human-like pace; 0 for none)
     */
    public record Options(URI server, String create, int seats, List<String> serverBots, boolean listed, String room,
                          String name, String level, Path seatFile, long thinkMillis) {
    }

    /** Waited for before joining (the benchmark holds each room's last player until every room is nearly full). */
    private java.util.concurrent.CountDownLatch joinGate;

    /** Joins only once {@code gate} opens (a room's last seat: its round starts when it is taken). */
    public HeadlessPlayer joinAfter(java.util.concurrent.CountDownLatch gate) {
        joinGate = gate;
        return this;
    }

    /** Spread of the pause before each shot: 0 (every pause is thinkMillis) or a fraction up to 1. */
    private double thinkSpread;
    private java.util.SplittableRandom thinkRandom;

    /**
     * Makes each pause before a shot vary uniformly within {@code thinkMillis × (1 ± spread)}, drawn from
     * {@code seed}: people do not aim for exactly the same time, and the benchmark's rooms, all playing
     * the same course with the same bot, would otherwise shoot in lock-step (every room at the same
     * instant, hole after hole).
     */
    public HeadlessPlayer thinkSpread(double spread, long seed) {
        if (!(spread >= 0 && spread <= 1)) throw new IllegalArgumentException("think spread must be 0 to 1: " + spread);
        thinkSpread = spread;
        thinkRandom = new java.util.SplittableRandom(seed);
        return this;
    }

    /** Sends a shot again that has had no answer for {@code wait} ({@link #RESEND_AFTER} unless set). */
    public HeadlessPlayer resendAfter(Duration wait) {
        if (wait.isNegative() || wait.isZero()) throw new IllegalArgumentException("resend wait must be positive: " + wait);
        resendNanos = wait.toNanos();
        return this;
    }

    /** This turn's pause before the shot, in nanoseconds. */
    long thinkNanos() {
        double factor = thinkRandom == null || thinkSpread == 0 ? 1 : 1 + thinkSpread * (2 * thinkRandom.nextDouble() - 1);
        return Math.round(options.thinkMillis() * factor * 1_000_000);
    }

    /** Hooks for the benchmark: a shot sent (with the room's event count) and its stroke received. */
    public interface Timing {
        /** This player's shot for seat {@code seat} left at {@code nanos}, the room being at event {@code seq}. */
        void shotSent(long seq, int seat, long nanos);

        /** The stroke numbered {@code seq} (seat, hole counted from 0) arrived at {@code nanos}. */
        void strokeReceived(long seq, int seat, int hole, long nanos);

        /** The player holds its seat now (its connection is open). */
        default void seated() {
        }
    }

    /** Connection retries: the first after 0.25 s, doubling to 8 s, for at most this long in all. */
    static final Duration RECONNECT_FOR = Duration.ofMinutes(5);

    private final Options options;
    private final Consumer<String> out;
    private final Consumer<String> log;
    private final Timing timing;
    private final BlockingQueue<Object> inbox = new LinkedBlockingQueue<>();
    private final RoomMirror mirror = new RoomMirror();
    private OnlineClient client;
    private boolean printedRoom;
    /** The last messages taken in, for a report on a player that never ends. */
    private final java.util.List<String> recent = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
    /** The seat came from the seat file: the room's code was printed by the run that created it. */
    private boolean resumed;
    private long shotAt = -1;
    /** After a refusal, the shot is sent again no sooner than this (System.nanoTime). */
    private long retryAt = Long.MIN_VALUE;
    /** How long after a refusal the player tries its shot again (the server's rate limit refills meanwhile). */
    static final long RETRY_NANOS = 1_000_000_000L;
    /**
     * A shot with no answer at all (no stroke, no refusal) for this long is sent again: a message lost on its
     * way (the server drops a message over its rate limit without a reply when it replied to one within the
     * second) would otherwise leave the seat, and its room, waiting for good. Longer than the slowest answer
     * measured (25.3 s, 1,000 players at the start of every round: docs/online.md); a shot that was only slow
     * is refused as stale when sent again, so no stroke is played twice.
     */
    public static final Duration RESEND_AFTER = Duration.ofSeconds(30);
    private long resendNanos = RESEND_AFTER.toNanos();
    /** When this seat's unanswered shot left (System.nanoTime). */
    private long shotSentNanos;

    public HeadlessPlayer(Options options, Consumer<String> out, Consumer<String> log, Timing timing) {
        this.options = options;
        this.out = out;
        this.log = log;
        this.timing = timing;
    }

    /** The last messages this player took in (type, and the problem for errors), for reports. */
    public String recentMessages() {
        synchronized (recent) {
            return String.join(", ", recent) + "; seat " + mirror.seat() + " turn " + mirror.turn() + " seq " + mirror.seq()
                    + " shotAt " + shotAt + " status " + mirror.status();
        }
    }

    /** Why the player stopped early: one line for the user. */
    public static final class Failure extends Exception {
        public Failure(String message) {
            super(message);
        }
    }

    private record Closed(OnlineClient client, String reason) {
    }

    /** A message with the moment it arrived (the benchmark times strokes by arrival, not by when they were read). */
    private record Arrived(ObjectNode message, long nanos) {
    }

    /** Plays to the end of the round and prints the scorecard; the room's code first when it created the room. */
    public void run() throws Failure, InterruptedException {
        SeatFile saved = SeatFile.read(options.seatFile());
        if (joinGate != null && saved == null && options.create() == null) joinGate.await();
        connect(true);
        resumed = saved != null;
        if (saved != null) {
            client.send(new ClientMessage.Resume(saved.room(), saved.token()));
        } else if (options.create() != null) {
            client.send(new ClientMessage.Create(options.name(), options.create(), options.seats(), options.serverBots(),
                    options.listed(), Game.DEFAULT_STROKE_LIMIT));
        } else {
            client.send(new ClientMessage.Join(options.room(), options.name()));
        }
        long thinkingAt = -1, thinkUntil = 0;
        while (true) {
            // On this seat's turn the player thinks for a while (messages are taken in meanwhile), then shoots.
            long waitMillis = 30_000;
            if (mirror.isMyTurn() && shotAt != mirror.seq()) {
                long now = System.nanoTime();
                if (thinkingAt != mirror.seq()) {
                    thinkingAt = mirror.seq();
                    thinkUntil = now + thinkNanos();
                }
                long shootAt = Math.max(thinkUntil, retryAt);
                if (now - shootAt >= 0) {
                    shoot();
                    continue;
                }
                waitMillis = Math.max(1, (shootAt - now) / 1_000_000);
            } else if (mirror.isMyTurn() && shotAt == mirror.seq()) {
                long now = System.nanoTime(), resendAt = shotSentNanos + resendNanos;
                if (now - resendAt >= 0) {
                    log.accept(String.format(java.util.Locale.ROOT, "no answer to the shot at event %d for %.0f s; sending it again",
                            shotAt, resendNanos / 1e9));
                    shotAt = -1;
                    continue;
                }
                waitMillis = Math.max(1, Math.min(waitMillis, (resendAt - now) / 1_000_000));
            }
            Object item = inbox.poll(waitMillis, TimeUnit.MILLISECONDS);
            if (item == null) {
                if (waitMillis == 30_000) client.send(new ClientMessage.Ping());
                continue;
            }
            if (item instanceof Closed c) {
                if (c.client() != client) continue; // a connection already replaced
                if (mirror.token() == null && saved == null) throw new Failure(c.reason());
                reconnect(c.reason(), saved);
                continue;
            }
            Arrived a = (Arrived) item;
            ObjectNode m = a.message();
            RoomMirror.Update u = mirror.apply(m, a.nanos() / 1_000_000);
            if (!"pong".equals(m.path("type").asText())) { // an idle player's pongs would push out what matters
                recent.add(m.path("type").asText() + (u.change() == RoomMirror.Change.OUT_OF_STEP || u.change() == RoomMirror.Change.ERROR
                        ? "(" + u.code() + ": " + u.text() + ")" : "") + "@" + mirror.seq());
                while (recent.size() > 8) recent.remove(0);
            }
            switch (u.change()) {
                case JOINED -> {
                    joined();
                    if (timing != null) timing.seated();
                }
                case ERROR -> error(u);
                case OUT_OF_STEP -> client.send(new ClientMessage.Sync());
                case EVENT -> {
                    if (timing != null) timing.strokeReceived(u.event().seq(), u.event().seat(), u.event().hole(), a.nanos());
                }
                case NOTICE, CHAT -> log.accept(u.text());
                default -> {
                }
            }
            if ("finished".equals(mirror.status()) && mirror.round() != null && mirror.round().isOver()) {
                out.accept(Json.write(scorecard(mirror)));
                client.close();
                return;
            }
        }
    }

    private void joined() {
        if (!printedRoom && options.create() != null && !resumed) {
            out.accept("{\"room\": \"" + mirror.room() + "\"}");
        }
        printedRoom = true;
        if (mirror.token() != null && options.seatFile() != null) {
            SeatFile.write(options.seatFile(), new SeatFile(mirror.room(), mirror.seat(), mirror.token()), log);
        }
    }

    private void error(RoomMirror.Update u) throws Failure {
        // An error while this seat's shot is unanswered may be its refusal (rate-limited, stale, ...): the player tries
        // again a little later, unless the stroke comes meanwhile. Without this a refused shot left the seat waiting
        // forever, and with it its whole room. The server checks the event count, so no stroke is played twice.
        if (shotAt >= 0 && shotAt == mirror.seq()) {
            shotAt = -1;
            retryAt = System.nanoTime() + RETRY_NANOS;
        }
        switch (u.code()) {
            case "stale" -> client.send(new ClientMessage.Sync());
            case "not-your-turn", "rate-limited", "not-playing" -> log.accept("server: " + u.text());
            default -> {
                if (mirror.seat() < 0) throw new Failure(u.text());
                log.accept("server: " + u.text());
            }
        }
    }

    private void shoot() {
        shotAt = mirror.seq();
        Game g = mirror.round().game();
        int seat = mirror.seat();
        PlayerState p = g.player(seat);
        // Planned for the room's clock as this client reckons it now; the server hits it at its own reading plus the wait.
        double[] v = plan(options.level(), g, seat, p, mirror.room().hashCode() * 31L + mirror.seq(),
                mirror.clockAt(RoomMirror.nowMs()));
        double ground = Math.hypot(v[0], v[1]);
        double speed = Math.sqrt(ground * ground + v[2] * v[2]);
        double loft = Math.min(Loft.MAX_DEGREES, Loft.degreesOf(v[0], v[1], v[2]));
        double ax = ground > 0 ? v[0] / ground * speed : 0, ay = ground > 0 ? v[1] / ground * speed : speed;
        shotSentNanos = System.nanoTime();
        if (timing != null) timing.shotSent(mirror.seq(), seat, shotSentNanos);
        client.send(new ClientMessage.Shot(mirror.seq(), ax, ay, loft, v[3]));
    }

    /** The bot's shot (vx, vy, vz) within the course's speed limit and its wait (s), planned at course clock {@code clock}. */
    static double[] plan(String level, Game g, int seat, PlayerState p, long seed, double clock) {
        ShotPlanner planner = BotCatalog.planner(level);
        double max = g.world().physics().maxSpeed();
        BotConditions now = BotConditions.of(g, seat, false);
        double[] v = planner.plan(g.world(), g.settings(), p.x(), p.y(), p.total(), seed,
                new BotConditions(now.noise(), now.hideFriction(), now.ownStrokes(), clock), new BotControl());
        double vz = v.length >= 3 ? Math.max(0, v[2]) : 0;
        double wait = v.length == 4 ? Math.min(Protocol.MAX_WAIT_SECONDS, Math.max(0, v[3])) : 0;
        double speed = Math.sqrt(v[0] * v[0] + v[1] * v[1] + vz * vz);
        double k = speed > max ? max / speed : 1;
        return new double[]{v[0] * k, v[1] * k, vz * k, wait};
    }

    private void connect(boolean first) throws Failure {
        try {
            OnlineClient[] self = new OnlineClient[1];
            client = OnlineClient.connect(options.server(), new OnlineClient.Listener() {
                public void onMessage(ObjectNode message) {
                    inbox.add(new Arrived(message, System.nanoTime()));
                }

                public void onClosed(String reason) {
                    inbox.add(new Closed(self[0], reason));
                }
            }, Duration.ofSeconds(10));
            self[0] = client;
        } catch (IOException e) {
            if (first) throw new Failure(e.getMessage());
            client = null;
        }
    }

    /** Connects again and resumes the seat, retrying with growing pauses. */
    private void reconnect(String reason, SeatFile saved) throws Failure, InterruptedException {
        log.accept(reason + "; reconnecting");
        String room = mirror.room() != null ? mirror.room() : saved.room();
        String token = mirror.token() != null ? mirror.token() : saved.token();
        long deadline = System.nanoTime() + RECONNECT_FOR.toNanos();
        long pause = 250;
        inbox.clear();
        while (System.nanoTime() < deadline) {
            Thread.sleep(pause);
            connect(false);
            if (client != null) {
                client.send(new ClientMessage.Resume(room, token));
                shotAt = -1;
                return;
            }
            pause = Math.min(8000, pause * 2);
        }
        throw new Failure("the server stayed unreachable for " + RECONNECT_FOR.toMinutes() + " minutes: " + reason);
    }

    /** The final card: {@code {"room", "course", "players": [{"name", "strokes": [per hole], "total"}]}}. */
    public static ObjectNode scorecard(RoomMirror mirror) {
        RoundScorecard card = mirror.round().scorecard();
        ObjectNode o = Json.object().put("room", mirror.room()).put("course", mirror.course());
        ArrayNode players = o.putArray("players");
        for (RoundScorecard.Row row : card.rows()) {
            ObjectNode p = players.addObject().put("name", row.name());
            ArrayNode strokes = p.putArray("strokes");
            for (int s : row.holes()) strokes.add(s);
            p.put("total", row.total());
        }
        return o;
    }

    /** The seat a client holds, kept in a file so that a restarted client resumes it. */
    record SeatFile(String room, int seat, String token) {
        static SeatFile read(Path file) {
            if (file == null || !Files.isRegularFile(file)) return null;
            try {
                JsonNode o = Json.parse(Files.readString(file, StandardCharsets.UTF_8));
                return new SeatFile(Json.matching(o, "room", Protocol.CODE, "a room code"), (int) Json.integer(o, "seat", 0, 3),
                        Json.matching(o, "token", Protocol.TOKEN, "a seat token"));
            } catch (IOException | ProtocolException e) {
                return null;
            }
        }

        static void write(Path file, SeatFile s, Consumer<String> log) {
            try {
                AtomicFile.write(file, Json.write(Json.object().put("room", s.room()).put("seat", s.seat()).put("token", s.token()))
                        .getBytes(StandardCharsets.UTF_8));
            } catch (IOException e) {
                log.accept("cannot write the seat file " + file + ": " + e.getMessage());
            }
        }
    }
}
