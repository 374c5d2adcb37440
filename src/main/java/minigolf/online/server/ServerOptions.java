package minigolf.online.server;

import java.nio.file.Path;

/**
 * How a server runs (docs/online.md, "Running a server"): where it listens, its database and
 * courses, the timeouts for dropped players and the limits that keep one client from hurting the
 * others.
 *
 * @param awayTimeoutSeconds   a dropped player's turn is passed over this long after the drop
 * @param pickupTimeoutSeconds when only dropped players are left on a hole, they pick up this long after their drop
 * @param messagesPerSecond    each connection's sustained message rate ...
 * @param messageBurst         ... and burst; messages beyond are answered "rate-limited" and dropped
 * @param connectionsPerAddress most open connections from one IP address
 * @param openRoomsPerAddress  most rooms not yet finished that one IP address has created
 * @param maxRooms             most rooms in play at once (lobby or playing)
 * @param botThreads           threads for the server's bots (they think for seconds)
 */
public record ServerOptions(String host, int port, String database, Path courses, double awayTimeoutSeconds,
                            double pickupTimeoutSeconds, double messagesPerSecond, int messageBurst,
                            int connectionsPerAddress, int openRoomsPerAddress, int maxRooms, int botThreads) {
    public static final double AWAY_TIMEOUT = 30;
    public static final double PICKUP_TIMEOUT = 120;

    public static ServerOptions defaults(int port, String database, Path courses) {
        return new ServerOptions("0.0.0.0", port, database, courses, AWAY_TIMEOUT, PICKUP_TIMEOUT, 10, 30, 16, 8, 10_000,
                Math.max(1, Runtime.getRuntime().availableProcessors() - 1));
    }

    public ServerOptions withHost(String h) {
        return new ServerOptions(h, port, database, courses, awayTimeoutSeconds, pickupTimeoutSeconds, messagesPerSecond,
                messageBurst, connectionsPerAddress, openRoomsPerAddress, maxRooms, botThreads);
    }

    public ServerOptions withTimeouts(double away, double pickup) {
        return new ServerOptions(host, port, database, courses, away, pickup, messagesPerSecond, messageBurst,
                connectionsPerAddress, openRoomsPerAddress, maxRooms, botThreads);
    }

    public ServerOptions withAddressLimits(int connections, int openRooms) {
        return new ServerOptions(host, port, database, courses, awayTimeoutSeconds, pickupTimeoutSeconds, messagesPerSecond,
                messageBurst, connections, openRooms, maxRooms, botThreads);
    }

    public ServerOptions withRate(double perSecond, int burst) {
        return new ServerOptions(host, port, database, courses, awayTimeoutSeconds, pickupTimeoutSeconds, perSecond, burst,
                connectionsPerAddress, openRoomsPerAddress, maxRooms, botThreads);
    }
}
