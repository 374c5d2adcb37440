package minigolf.online.server;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import minigolf.online.Protocol;
import minigolf.online.store.GameStore;
import minigolf.online.store.StoreException;

/**
 * The online game server (docs/online.md): Jetty 12's WebSocket endpoint {@value Protocol#PATH} for
 * the game's clients and the web pages, on one port; the rooms; the database. Start-up restores every
 * room that was in its lobby or in play from the database.
 */
public final class GameServer implements AutoCloseable {
    private final Server jetty;
    private final GameStore store;
    private final Rooms rooms;
    private final RoomServices svc;
    private final int restored;

    private GameServer(Server jetty, GameStore store, Rooms rooms, RoomServices svc, int restored) {
        this.jetty = jetty;
        this.store = store;
        this.rooms = rooms;
        this.svc = svc;
        this.restored = restored;
    }

    /** Opens the database, restores the rooms and starts listening. */
    public static GameServer start(ServerOptions o, CourseCatalog catalog, PrintWriter log) throws StoreException, Exception {
        GameStore store = GameStore.open(o.database());
        ExecutorService roomPool = Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()),
                daemon("minigolf-room"));
        ExecutorService botPool = Executors.newFixedThreadPool(o.botThreads(), daemon("minigolf-bot"));
        ScheduledExecutorService timers = Executors.newSingleThreadScheduledExecutor(daemon("minigolf-timer"));
        RoomServices svc = new RoomServices(store, roomPool, botPool, timers, o, System::currentTimeMillis, log);
        Rooms rooms = new Rooms(catalog, svc);
        int restored;
        try {
            restored = rooms.restore();
        } catch (StoreException e) {
            store.close();
            throw e;
        }
        timers.scheduleAtFixedRate(rooms::sweep, 10, 10, TimeUnit.MINUTES);

        QueuedThreadPool threads = new QueuedThreadPool(200, 8);
        threads.setName("minigolf-http");
        threads.setDaemon(true);
        Server jetty = new Server(threads);
        ServerConnector connector = new ServerConnector(jetty);
        connector.setHost(o.host());
        connector.setPort(o.port());
        jetty.addConnector(connector);
        Map<String, AtomicInteger> perAddress = new ConcurrentHashMap<>();
        WebSocketUpgradeHandler ws = WebSocketUpgradeHandler.from(jetty, container -> {
            container.setMaxTextMessageSize(Protocol.MAX_FRAME_BYTES);
            container.setMaxBinaryMessageSize(1024);
            container.setIdleTimeout(Duration.ofMinutes(2));
            container.setMaxOutgoingFrames(1000);
            container.addMapping(Protocol.PATH, (request, response, callback) -> {
                String address = Request.getRemoteAddr(request);
                AtomicInteger n = perAddress.computeIfAbsent(address, a -> new AtomicInteger());
                if (n.incrementAndGet() > o.connectionsPerAddress()) {
                    n.decrementAndGet();
                    Response.writeError(request, response, callback, 429, "too many connections from this address");
                    return null;
                }
                return new Connection(rooms, address, o, () -> {
                    if (n.decrementAndGet() <= 0) perAddress.remove(address, n);
                });
            });
        });
        ws.setHandler(new WebPages(rooms, store));
        jetty.setHandler(ws);
        jetty.setStopTimeout(2000);
        try {
            jetty.start();
        } catch (Exception e) {
            store.close();
            throw e;
        }
        return new GameServer(jetty, store, rooms, svc, restored);
    }

    private static java.util.concurrent.ThreadFactory daemon(String name) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, name + "-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    /** The port it listens on (the one asked for, or the one chosen for port 0). */
    public int port() {
        return ((ServerConnector) jetty.getConnectors()[0]).getLocalPort();
    }

    /** How many rooms start-up restored from the database. */
    public int restoredRooms() {
        return restored;
    }

    Rooms rooms() {
        return rooms;
    }

    GameStore store() {
        return store;
    }

    public String database() {
        return store.description();
    }

    /** Blocks until the server stops. */
    public void join() throws InterruptedException {
        jetty.join();
    }

    @Override
    public void close() {
        try {
            jetty.stop();
        } catch (Exception e) {
            svc.log("stopping: " + e.getMessage());
        }
        svc.timers().shutdownNow();
        svc.botPool().shutdownNow();
        svc.roomPool().shutdown();
        try {
            svc.roomPool().awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        store.close();
    }
}
