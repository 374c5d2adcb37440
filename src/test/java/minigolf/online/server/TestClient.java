package minigolf.online.server;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import minigolf.online.ClientMessage;
import minigolf.online.client.OnlineClient;
import minigolf.online.client.RoomMirror;

/** A test's WebSocket client: every message kept in order, waited for by type or by content, and mirrored. */
final class TestClient implements AutoCloseable {
    final OnlineClient socket;
    final RoomMirror mirror = new RoomMirror();
    private final LinkedBlockingQueue<ObjectNode> inbox = new LinkedBlockingQueue<>();
    final List<ObjectNode> seen = new ArrayList<>();
    volatile String closedReason;

    TestClient(URI uri) throws IOException {
        socket = OnlineClient.connect(uri, new OnlineClient.Listener() {
            public void onMessage(ObjectNode message) {
                inbox.add(message);
            }

            public void onClosed(String reason) {
                closedReason = reason;
            }
        }, Duration.ofSeconds(10));
    }

    static TestClient to(GameServer server) throws IOException {
        return new TestClient(OnlineClient.uri("127.0.0.1:" + server.port()));
    }

    void send(ClientMessage m) {
        socket.send(m);
    }

    /** The next message of this type (others are applied to the mirror and kept in {@link #seen}). */
    ObjectNode await(String type) throws InterruptedException {
        return await(m -> m.path("type").asText().equals(type), "a " + type + " message");
    }

    ObjectNode await(Predicate<ObjectNode> wanted, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            ObjectNode m = inbox.poll(100, TimeUnit.MILLISECONDS);
            if (m == null) continue;
            seen.add(m);
            mirror.apply(m);
            if (wanted.test(m)) return m;
        }
        throw new AssertionError("no " + what + " within 60 s; seen: " + seen);
    }

    /** Waits until {@code state} holds, checking now and after every message. */
    void awaitState(java.util.function.BooleanSupplier state, String what) throws InterruptedException {
        if (state.getAsBoolean()) return;
        await(m -> state.getAsBoolean(), what);
    }

    /** Waits until the mirror says it is this client's turn. */
    void awaitMyTurn() throws InterruptedException {
        if (mirror.isMyTurn()) return;
        await(m -> mirror.isMyTurn(), "turn for seat " + mirror.seat());
    }

    /** Plays a putt (vx, vy) at the room's current event count and returns the stroke message. */
    ObjectNode putt(double vx, double vy) throws InterruptedException {
        awaitMyTurn();
        long seq = mirror.seq();
        send(new ClientMessage.Shot(seq, vx, vy, 0, 0));
        return await(m -> m.path("type").asText().equals("stroke") && m.path("seq").asLong() == seq + 1, "stroke " + (seq + 1));
    }

    /** The client whose turn it is, once all of them have seen the same events; null once the round is over. */
    static TestClient whoseTurn(TestClient... clients) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            long seq = -1;
            boolean same = true;
            TestClient turn = null;
            for (TestClient c : clients) {
                c.drain();
                if (seq >= 0 && c.mirror.seq() != seq) same = false;
                seq = c.mirror.seq();
                if (c.mirror.isMyTurn()) turn = c;
            }
            if (same && turn != null) return turn;
            if (same && clients[0].mirror.round() != null && clients[0].mirror.round().isOver()) return null;
            Thread.sleep(10);
        }
        throw new AssertionError("nobody's turn within 60 s");
    }

    /** Messages waiting, applied (a drain before asserting that nothing else came). */
    List<ObjectNode> drain() {
        List<ObjectNode> out = new ArrayList<>();
        inbox.drainTo(out);
        for (ObjectNode m : out) {
            seen.add(m);
            mirror.apply(m);
        }
        return out;
    }

    @Override
    public void close() {
        socket.close();
    }
}
