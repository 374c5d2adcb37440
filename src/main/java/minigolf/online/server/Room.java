package minigolf.online.server;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import minigolf.game.BotConditions;
import minigolf.game.BotControl;
import minigolf.game.BotCatalog;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.ShotPlanner;
import minigolf.game.ShotRecord;
import minigolf.online.ClientMessage;
import minigolf.online.RoomClock;
import minigolf.online.RoomEvent;
import minigolf.online.RoundSync;
import minigolf.online.store.Score;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Stroke;
import minigolf.physics.World;

/**
 * One room: its seats, its round and the rules of online play (docs/online.md, "Rules"). Every
 * method runs on the room's {@link Actor}, so a room's state has one writer; the public entry
 * points only queue work there.
 *
 * <p>The server is authoritative: a client's shot is checked (its seat, its turn, the room's event
 * count, the course's speed limit), simulated with the game's engine, stored, and only then sent to
 * every client. A dropped player's turn is passed over {@code awayTimeout} after the drop; when only
 * dropped players are left on a hole they pick up {@code pickupTimeout} after it (at once for a
 * player who left). A room nobody is connected to waits, unchanged.
 */
final class Room {
    enum Status {
        LOBBY, PLAYING, FINISHED;

        String jsonName() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** Every room plays with the game's default integration (clients animate with the same). */
    static final SimulationSettings SETTINGS = SimulationSettings.DEFAULT;
    /** A bot's next stroke waits for the previous ball to stop on screen, but never longer than this (s). */
    private static final double MAX_ROLL_WAIT = 12;
    /**
     * Where obstacles move, a bot plans its shot for the room's clock at least this long ahead (ms),
     * doubled on each try that finished too late to be hit at its planned moment.
     */
    private static final long BOT_PLAN_AHEAD_MS = 3000;
    private static final int BOT_PLAN_TRIES = 3;

    final String code;
    final CourseCatalog.Entry entry;
    final boolean listed;
    final int strokeLimit;
    final long createdMs;
    final String creatorAddress;
    final Actor actor;
    private final Seat[] seats;
    private final RoomServices svc;
    private final RoomMessages messages = new RoomMessages(this);
    private Status status;
    private RoundGame round;
    /** The round as it started (a saved round's text), and every event's message since, in order. */
    private String startSave;
    private final List<String> events = new ArrayList<>();
    private long seq;
    private ScheduledFuture<?> timer;
    private long botThinkingAt = -1;
    /** When the last stroke's ball stops rolling on the clients' screens (ms). */
    private long quietAtMs;
    /** The room's course clock (moving obstacles): the server's own, every stroke is played at it. */
    private volatile RoomClock clock = RoomClock.startingAt(0);
    private volatile RoomView view;

    Room(String code, CourseCatalog.Entry entry, boolean listed, int strokeLimit, long createdMs, String creatorAddress,
         Seat[] seats, RoomServices svc) {
        this.code = code;
        this.entry = entry;
        this.listed = listed;
        this.strokeLimit = strokeLimit;
        this.createdMs = createdMs;
        this.creatorAddress = creatorAddress;
        this.seats = seats;
        this.svc = svc;
        this.status = Status.LOBBY;
        this.actor = new Actor(svc.roomPool(), e -> svc.log("room " + code + ": internal error: " + e));
        refreshView();
    }

    /** A room rebuilt from the database: its round as it started and every stored event settled in order. */
    void restore(Status stored, String startText, RoundGame started, List<String> storedEvents) throws minigolf.online.ProtocolException {
        status = stored;
        startSave = startText;
        round = started;
        for (String json : storedEvents) {
            RoomEvent e = RoomEvent.parse(minigolf.online.Json.parse(json), seats.length);
            if (e.seq() != seq + 1) throw new IllegalStateException("event " + e.seq() + " follows event " + seq);
            round = RoundSync.apply(round, e);
            seq = e.seq();
            events.add(json);
        }
        if (round != null && round.isOver()) status = Status.FINISHED;
        long now = svc.now();
        // The clock runs on from where the last stroke left it (a restart loses only the time the server was down).
        clock = new RoomClock(round != null ? round.game().clock() : 0, now);
        for (Seat s : seats) if (s.isTaken() && !s.bot) s.awaySinceMs = now;
        refreshView();
    }

    // ---- entry points (any thread) ----

    void join(Client c, String name) {
        actor.execute(() -> doJoin(c, name));
    }

    void resume(Client c, String token) {
        actor.execute(() -> doResume(c, token));
    }

    void message(Client c, int seat, ClientMessage m) {
        long arrived = System.nanoTime();
        actor.execute(() -> {
            if (seat < 0 || seat >= seats.length || seats[seat].client != c) {
                c.send(messages.error("not-seated", "this connection holds no seat in room " + code));
            } else if (m instanceof ClientMessage.Shot shot) {
                doShot(c, seat, shot, new StrokeTimes(arrived, System.nanoTime()));
            } else if (m instanceof ClientMessage.Chat chat) {
                broadcast(messages.chat(seat, chat.text()));
            } else if (m instanceof ClientMessage.Leave) {
                doLeave(c, seat);
            }
        });
    }

    /** Sends the whole state again to a seated client that asked. */
    void sync(Client c, int seat) {
        actor.execute(() -> {
            if (seats[seat].client == c) c.send(messages.snapshot());
        });
    }

    void disconnected(Client c, int seat) {
        actor.execute(() -> {
            Seat s = seats[seat];
            if (s.client != c) return;
            s.client = null;
            s.awaySinceMs = svc.now();
            broadcast(messages.notice(s.name + " lost the connection"));
            seatsChanged();
        });
    }

    /** Sends the room's state to a newly seated client (after its seat was stored). */
    void welcome(Client c, int seat, String token) {
        c.send(messages.joined(seat, token));
        c.send(messages.snapshot());
    }

    // ---- on the room's thread ----

    private void doJoin(Client c, String name) {
        if (status != Status.LOBBY) {
            c.seated(null, -1);
            c.send(messages.error("room-full", "room " + code + " has started; its players resume with their tokens"));
            return;
        }
        Seat free = null;
        for (Seat s : seats) {
            if (!s.isTaken()) {
                free = s;
                break;
            }
        }
        if (free == null) {
            c.seated(null, -1);
            c.send(messages.error("room-full", "room " + code + " has no free seat"));
            return;
        }
        String token = Secrets.token();
        Seat seat = free;
        seat.name = uniqueName(name);
        seat.tokenHash = Secrets.hash(token);
        seat.client = c;
        c.seated(this, seat.index);
        svc.store().addSeat(code, seat.stored()).whenComplete((v, err) -> actor.execute(() -> {
            if (err != null) {
                svc.log("room " + code + ": seat not stored: " + err.getMessage());
                seat.name = null;
                seat.tokenHash = null;
                seat.client = null;
                c.seated(null, -1);
                c.send(messages.error("server", "the server could not store the seat; try again"));
                return;
            }
            welcome(c, seat.index, token);
            broadcast(messages.notice(seat.name + " joined"));
            if (allTaken()) {
                start();
            } else {
                broadcast(messages.snapshot());
                refreshView();
            }
        }));
    }

    private String uniqueName(String name) {
        String n = name;
        for (int k = 2; nameTaken(n); k++) {
            String suffix = " " + k;
            n = (name.length() + suffix.length() > Player.MAX_NAME_LENGTH
                    ? name.substring(0, Player.MAX_NAME_LENGTH - suffix.length()) : name) + suffix;
        }
        return n;
    }

    private boolean nameTaken(String n) {
        for (Seat s : seats) if (n.equals(s.name)) return true;
        return false;
    }

    private boolean allTaken() {
        for (Seat s : seats) if (!s.isTaken()) return false;
        return true;
    }

    /** Every seat is taken: the round begins with the seats in order. */
    void start() {
        List<Player> players = new ArrayList<>();
        for (Seat s : seats) players.add(s.bot ? Player.bot(s.name, s.level) : Player.human(s.name));
        round = new RoundGame(entry.round(), SETTINGS, players, strokeLimit);
        status = Status.PLAYING;
        clock = RoomClock.startingAt(svc.now());
        startSave = SavedRounds.toJson(round);
        svc.store().startRoom(code, startSave, svc.now()).whenComplete((v, err) -> actor.execute(() -> {
            if (err != null) svc.log("room " + code + ": start not stored: " + err.getMessage());
            broadcast(messages.snapshot());
            refreshView();
            updateTurn();
        }));
    }

    private void doResume(Client c, String token) {
        Seat seat = null;
        for (Seat s : seats) if (!s.bot && Secrets.matches(token, s.tokenHash)) seat = s;
        if (seat == null) {
            c.seated(null, -1);
            c.send(messages.error("bad-token", "that token holds no seat in room " + code));
            return;
        }
        if (seat.gone) {
            c.seated(null, -1);
            c.send(messages.error("left", seat.name + " left room " + code + " for good"));
            return;
        }
        if (seat.client != null && seat.client != c) {
            Client old = seat.client;
            old.seated(null, -1);
            old.close(4000, "the seat was taken back by a new connection");
        }
        boolean wasAway = seat.client == null;
        seat.client = c;
        seat.awaySinceMs = 0;
        c.seated(this, seat.index);
        welcome(c, seat.index, null);
        if (wasAway) broadcast(messages.notice(seat.name + " is back"));
        seatsChanged();
    }

    /**
     * When a player's shot reached the server and when the room's thread took it up (System.nanoTime);
     * a stroke that goes out {@link #SLOW_STROKE_MS} or more after its shot arrived is reported on the
     * server's log with where the time went (docs/online.md, "Benchmarks").
     */
    record StrokeTimes(long arrived, long taken) {
    }

    static final long SLOW_STROKE_MS = 1000;

    private void doShot(Client c, int seat, ClientMessage.Shot m, StrokeTimes times) {
        if (status != Status.PLAYING) {
            c.send(messages.error("not-playing", status == Status.LOBBY ? "the round has not started" : "the round is over"));
            return;
        }
        if (m.seq() != seq) {
            c.send(messages.error("stale", "the room is at event " + seq + ", the shot was sent at " + m.seq()));
            return;
        }
        Game g = round.game();
        if (g.currentPlayer() != seat) {
            c.send(messages.error("not-your-turn", "it is " + seats[g.currentPlayer()].name + "'s turn"));
            return;
        }
        double max = g.world().physics().maxSpeed();
        double speed = Math.hypot(m.vx(), m.vy());
        if (!(speed <= max * (1 + 1e-9))) {
            c.send(messages.error("bad-field", String.format(java.util.Locale.ROOT,
                    "velocity: %.3f m/s is faster than the course's maxSpeed of %s m/s", speed, max)));
            return;
        }
        playStroke(seat, Loft.velocity(m.vx(), m.vy(), m.loft(), max), m.waitSeconds(), times);
    }

    /**
     * Plays a stroke with the engine and records it, at the room's clock when the shot arrived plus
     * its wait (where obstacles move it matters: docs/course-format.md, "Moving obstacles"). The
     * server's clock alone decides the moment: a client only says how long to wait.
     */
    private void playStroke(int seat, double[] v, double waitSeconds, StrokeTimes times) {
        long startMs = clock.strokeStart(svc.now(), waitSeconds);
        playStrokeAt(seat, v, waitSeconds, clock.at(startMs), startMs, times);
    }

    /**
     * Plays a stroke hit at course clock {@code at}, the moment {@code startMs} of the room's clock;
     * {@code times} of a player's shot (null for a bot's).
     */
    private void playStrokeAt(int seat, double[] v, double waitSeconds, double at, long startMs, StrokeTimes times) {
        Game g = round.game();
        int hole = round.holeIndex();
        int finishedBefore = round.holesFinished();
        g.advanceClockTo(Math.max(g.clock(), at));
        Stroke stroke = g.startShot(v[0], v[1], v[2], null);
        stroke.runOrEndOutOfPlay();
        double rollSeconds = stroke.result().time();
        ShotRecord record = g.completeShot();
        seq++;
        quietAtMs = startMs + (long) (1000 * Math.min(MAX_ROLL_WAIT, rollSeconds));
        double after = g.clock();
        recordEvent(new RoomEvent(seq, hole, seat, record, g.player(seat), waitSeconds, after), finishedBefore, times,
                System.nanoTime());
        clock = RoomClock.afterStroke(record.clock(), after, startMs, round.holesFinished() > finishedBefore);
    }

    private void pickUp(int seat) {
        Game g = round.game();
        int finishedBefore = round.holesFinished();
        int hole = round.holeIndex();
        g.pickUp(seat);
        seq++;
        broadcast(messages.notice(seats[seat].name + " picks up on hole " + (hole + 1) + " (away)"));
        recordEvent(new RoomEvent(seq, hole, seat, null, g.player(seat), 0), finishedBefore, null, 0);
        clock = clock.afterPickUp(svc.now(), round.holesFinished() > finishedBefore);
    }

    /**
     * Stores the event (with any scores it completes) and tells every client once it is stored;
     * {@code times} of a player's shot and when it was simulated, for the slow-stroke report.
     */
    private void recordEvent(RoomEvent event, int finishedBefore, StrokeTimes times, long simulated) {
        RoundSync.advance(round);
        if (round.isOver()) status = Status.FINISHED;
        List<Score> scores = scoresSince(finishedBefore);
        String json = minigolf.online.Json.write(event.toJson(turn()));
        events.add(json);
        svc.store().appendEvent(code, event.seq(), json, scores, status.jsonName(), svc.now())
                .whenComplete((v, err) -> actor.execute(() -> {
                    if (err != null) {
                        svc.log("room " + code + ": event " + event.seq() + " not stored: " + err.getMessage());
                        broadcast(messages.notice("the server could not store this stroke"));
                    }
                    broadcast(json);
                    if (times != null) reportIfSlow(event.seq(), times, simulated, System.nanoTime());
                    if (status == Status.FINISHED) broadcast(messages.snapshot());
                    refreshView();
                    updateTurn();
                }));
    }

    private void reportIfSlow(long seq, StrokeTimes t, long simulated, long sent) {
        long ms = (sent - t.arrived()) / 1_000_000;
        if (ms < SLOW_STROKE_MS) return;
        svc.log(String.format(java.util.Locale.ROOT, "room %s: stroke %d went out %d ms after its shot arrived "
                        + "(%d ms waiting for the room's thread, %d ms simulating, %d ms storing and sending)", code, seq, ms,
                (t.taken() - t.arrived()) / 1_000_000, (simulated - t.taken()) / 1_000_000, (sent - simulated) / 1_000_000));
    }

    /** The leaderboard entries of the holes finished since {@code finishedBefore}, and of the round once over. */
    private List<Score> scoresSince(int finishedBefore) {
        List<Score> out = new ArrayList<>();
        int[][] card = round.finishedScores();
        long now = svc.now();
        for (int h = finishedBefore; h < card.length; h++) {
            minigolf.game.Round.Hole hole = round.round().hole(h);
            String board = entry.isRound() ? boardOf(hole.course()) : entry.name();
            for (Seat s : seats) out.add(new Score(board, s.name, s.level, card[h][s.index], hole.par(), code, s.index, now));
        }
        if (entry.isRound() && round.isOver() && finishedBefore < card.length) {
            for (Seat s : seats) {
                int total = 0;
                for (int[] row : card) total += row[s.index];
                out.add(new Score(entry.name(), s.name, s.level, total, round.round().par(), code, s.index, now));
            }
        }
        return out;
    }

    /** A hole's leaderboard is its course file's name without folders and .json. */
    static String boardOf(String courseFile) {
        String n = courseFile.replace('\\', '/');
        n = n.substring(n.lastIndexOf('/') + 1);
        return n.endsWith(".json") ? n.substring(0, n.length() - 5) : n;
    }

    private void doLeave(Client c, int index) {
        Seat s = seats[index];
        c.seated(null, -1);
        s.client = null;
        if (status == Status.LOBBY) {
            // Not started: the seat is free again.
            String name = s.name;
            s.name = null;
            s.tokenHash = null;
            svc.store().removeSeat(code, index);
            broadcast(messages.notice(name + " left"));
            broadcast(messages.snapshot());
            refreshView();
            return;
        }
        s.gone = true;
        s.awaySinceMs = svc.now();
        svc.store().seatGone(code, index);
        broadcast(messages.notice(s.name + " left the game"));
        seatsChanged();
    }

    private void seatsChanged() {
        broadcast(messages.seats());
        refreshView();
        if (status == Status.PLAYING) updateTurn();
    }

    /** Whose turn it is (-1 outside play), with dropped players passed over. */
    int turn() {
        return status == Status.PLAYING ? round.game().currentPlayer() : -1;
    }

    /**
     * Applies the timeouts and starts what the turn needs: a bot's thinking, a pick-up, or a timer for
     * the next deadline. Runs after every change.
     */
    private void updateTurn() {
        if (timer != null) {
            timer.cancel(false);
            timer = null;
        }
        if (status != Status.PLAYING) return;
        boolean anyoneHere = false;
        for (Seat s : seats) anyoneHere |= !s.bot && s.client != null;
        if (!anyoneHere) return; // nobody to play for: the room waits as it is
        long now = svc.now();
        long awayMs = (long) (svc.options().awayTimeoutSeconds() * 1000);
        long next = Long.MAX_VALUE;
        Game g = round.game();
        boolean changed = false;
        for (Seat s : seats) {
            boolean passed = s.isAway() && (s.gone || now >= s.awaySinceMs + awayMs);
            if (passed != g.isPassedOver(s.index)) {
                changed = true;
                g.passOver(s.index, passed);
                if (passed) broadcast(messages.notice(s.name + "'s turns are passed over until " + (s.gone ? "the end" : "they are back")));
            }
            if (s.isAway() && !passed) next = Math.min(next, s.awaySinceMs + awayMs);
        }
        if (changed) {
            broadcast(messages.seats());
            refreshView();
        }
        int current = g.currentPlayer();
        if (current < 0) return;
        Seat s = seats[current];
        if (s.bot) {
            startBot(current);
        } else if (s.isAway() && g.isPassedOver(current)) {
            // Only dropped players are left on this hole.
            long pickAt = s.gone ? now : s.awaySinceMs + (long) (svc.options().pickupTimeoutSeconds() * 1000);
            if (now >= pickAt) {
                pickUp(current);
                return;
            }
            next = Math.min(next, pickAt);
        }
        if (next != Long.MAX_VALUE) {
            timer = svc.timers().schedule(() -> actor.execute(this::updateTurn), Math.max(1, next - now), TimeUnit.MILLISECONDS);
        }
    }

    private void startBot(int seat) {
        if (botThinkingAt == seq) return;
        botThinkingAt = seq;
        planBot(seat, seq, 0);
    }

    /**
     * A bot's turn: it plans on the bot threads and is hit once the last ball has stopped on the
     * clients' screens. Where obstacles move it plans for the room's clock a little ahead and is hit
     * exactly at the moment it planned (plus its wait); a plan that comes too late is made again
     * further ahead, and after {@value #BOT_PLAN_TRIES} tries it is hit at once.
     */
    private void planBot(int seat, long at, int attempt) {
        Game g = round.game();
        PlayerState p = g.player(seat);
        World world = g.world();
        boolean moving = world.moving() != null;
        String level = seats[seat].level;
        long ready = Math.max(svc.now() + (BOT_PLAN_AHEAD_MS << attempt), quietAtMs);
        double moment = clock.at(ready);
        BotConditions asked = BotConditions.of(g, seat, false);
        BotConditions conditions = new BotConditions(asked.noise(), asked.hideFriction(), asked.ownStrokes(), moment);
        long seed = code.hashCode() * 1_000_003L + at;
        svc.botPool().execute(() -> {
            double[] v = plan(level, world, p, seed, conditions);
            actor.execute(() -> {
                if (seq != at || status != Status.PLAYING || round.game().currentPlayer() != seat) return;
                RoomClock c = clock;
                double target = moment + v[3];
                // The moment the room's clock reads the planned one (it runs from c.base() at c.quietAtMs()).
                long hitMs = c.quietAtMs() + Math.round((target - c.base()) * 1000);
                long now = svc.now();
                Runnable hit;
                long delay;
                if (!moving || attempt + 1 >= BOT_PLAN_TRIES) {
                    hit = () -> playStroke(seat, v, 0, null);
                    delay = Math.max(0, quietAtMs - now);
                } else if (target >= c.base() && hitMs >= now) {
                    hit = () -> playStrokeAt(seat, v, 0, target, hitMs, null);
                    delay = hitMs - now;
                } else {
                    planBot(seat, at, attempt + 1);
                    return;
                }
                Runnable play = () -> actor.execute(() -> {
                    if (seq != at || status != Status.PLAYING || round.game().currentPlayer() != seat) return;
                    hit.run();
                });
                if (delay == 0) play.run();
                else svc.timers().schedule(play, delay, TimeUnit.MILLISECONDS);
            });
        });
    }

    /** A bot's shot {vx, vy, vz, wait} within the speed limit; a bot that fails plays the straight putt at the hole. */
    private static double[] plan(String level, World world, PlayerState p, long seed, BotConditions conditions) {
        double max = world.physics().maxSpeed();
        for (String name : new String[]{level, "straight"}) {
            ShotPlanner planner = BotCatalog.planner(name);
            if (planner == null) continue;
            try {
                double[] v = planner.plan(world, SETTINGS, p.x(), p.y(), p.total(), seed, conditions, new BotControl());
                if (v == null || v.length < 2 || v.length > 4) continue;
                double vz = v.length >= 3 ? v[2] : 0;
                double wait = v.length == 4 ? v[3] : 0;
                double speed = Math.sqrt(v[0] * v[0] + v[1] * v[1] + vz * vz);
                if (!Double.isFinite(speed) || vz < 0 || !(wait >= 0 && wait <= minigolf.online.Protocol.MAX_WAIT_SECONDS)) continue;
                double k = speed > max ? max / speed : 1;
                return new double[]{v[0] * k, v[1] * k, vz * k, wait};
            } catch (RuntimeException | StackOverflowError e) {
                // the fallback plays
            }
        }
        return new double[]{0, 0, 0, 0};
    }

    void broadcast(String json) {
        for (Seat s : seats) if (s.client != null) s.client.send(json);
    }

    private void refreshView() {
        view = RoomView.of(this);
    }

    // ---- read by RoomMessages and RoomView on the room's thread ----

    Seat[] seats() {
        return seats;
    }

    Status status() {
        return status;
    }

    RoundGame round() {
        return round;
    }

    long seq() {
        return seq;
    }

    /** The room's course clock. */
    RoomClock clock() {
        return clock;
    }

    /** The server's time (ms). */
    long now() {
        return svc.now();
    }

    String startSave() {
        return startSave;
    }

    List<String> events() {
        return events;
    }

    /** The room as the web page shows it, safe to read from any thread. */
    RoomView view() {
        return view;
    }
}
