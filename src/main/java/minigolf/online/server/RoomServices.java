package minigolf.online.server;

import java.io.PrintWriter;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ScheduledExecutorService;
import java.util.function.LongSupplier;
import minigolf.online.store.GameStore;

/** What every room of a server shares: its database, threads, options, clock and log. */
record RoomServices(GameStore store, ExecutorService roomPool, ExecutorService botPool, ScheduledExecutorService timers,
                    ServerOptions options, LongSupplier clockMs, PrintWriter log) {
    long now() {
        return clockMs.getAsLong();
    }

    void log(String line) {
        synchronized (log) {
            log.println("minigolf server: " + line);
            log.flush();
        }
    }
}
