package minigolf.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.online.server.CourseCatalog;
import minigolf.online.server.GameServer;
import minigolf.online.server.ServerOptions;
import minigolf.online.store.StoreException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

@Command(name = "server",
        description = "Runs the online game server: rooms for up to 4 players, the WebSocket protocol on /play, the web "
                + "page on / and /course/NAME, everything kept in the database (docs/online.md).")
final class ServerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--port", paramLabel = "N", required = true, description = "The TCP port (0: any free port, printed).")
    int port;

    @Option(names = "--db", paramLabel = "DB", description = "The database: an SQLite file, or a JDBC URL such as "
            + "jdbc:postgresql://HOST/DB?user=U&password=P (default: ${DEFAULT-VALUE}).")
    String db = "minigolf-server.db";

    @Option(names = "--host", paramLabel = "ADDRESS", description = "The address to listen on (default: ${DEFAULT-VALUE}; "
            + "127.0.0.1 behind a reverse proxy).")
    String host = "0.0.0.0";

    @Option(names = "--courses", paramLabel = "DIR", description = "The folder of courses (and holes/, rounds/) to offer "
            + "(default: the game's courses).")
    Path courses;

    @Option(names = "--away-timeout", paramLabel = "SECONDS", description = "A dropped player's turn is passed over this "
            + "long after the drop (default: ${DEFAULT-VALUE}).")
    double awayTimeout = ServerOptions.AWAY_TIMEOUT;

    @Option(names = "--pickup-timeout", paramLabel = "SECONDS", description = "When only dropped players are left on a "
            + "hole, they pick up this long after the drop (default: ${DEFAULT-VALUE}).")
    double pickupTimeout = ServerOptions.PICKUP_TIMEOUT;

    @Option(names = "--connections-per-address", paramLabel = "N", description = "Most connections from one IP address "
            + "(default: ${DEFAULT-VALUE}).")
    int connectionsPerAddress = 16;

    @Option(names = "--rooms-per-address", paramLabel = "N", description = "Most unfinished rooms one IP address may "
            + "open (default: ${DEFAULT-VALUE}).")
    int roomsPerAddress = 8;

    @Option(names = "--messages-per-second", paramLabel = "R", description = "Each connection's message rate; bursts of "
            + "3 s worth are allowed (default: ${DEFAULT-VALUE}).")
    double messagesPerSecond = 10;

    @Override
    public Integer call() throws Exception {
        if (port < 0 || port > 65535) throw new UserError("--port: must be 0 to 65535, got " + port);
        if (!(awayTimeout >= 0 && awayTimeout <= 86400)) throw new UserError("--away-timeout: must be 0 to 86400 s");
        if (!(pickupTimeout >= 0 && pickupTimeout <= 86400)) throw new UserError("--pickup-timeout: must be 0 to 86400 s");
        if (connectionsPerAddress < 1) throw new UserError("--connections-per-address: must be at least 1");
        if (roomsPerAddress < 1) throw new UserError("--rooms-per-address: must be at least 1");
        if (!(messagesPerSecond >= 1 && messagesPerSecond <= 10000)) throw new UserError("--messages-per-second: must be 1 to 10000");
        Path folder = courses != null ? courses : CourseCatalog.defaultFolder();
        if (!Files.isDirectory(folder)) throw new UserError("--courses: " + folder + " is not a folder");
        PrintWriter err = spec.commandLine().getErr();
        CourseCatalog catalog = CourseCatalog.load(folder, err);
        if (catalog.names().isEmpty()) throw new UserError("--courses: no course loads from " + folder);
        ServerOptions options = ServerOptions.defaults(port, db, folder).withHost(host)
                .withTimeouts(awayTimeout, pickupTimeout).withAddressLimits(connectionsPerAddress, roomsPerAddress)
                .withRate(messagesPerSecond, (int) Math.ceil(3 * messagesPerSecond));
        GameServer server;
        try {
            server = GameServer.start(options, catalog, err);
        } catch (StoreException e) {
            throw new UserError(e.getMessage());
        } catch (java.io.IOException e) {
            throw new UserError("cannot listen on " + host + ":" + port + ": " + e.getMessage());
        }
        Runtime.getRuntime().addShutdownHook(new Thread(server::close, "minigolf-server-stop"));
        PrintWriter out = spec.commandLine().getOut();
        out.println(minigolf.online.Json.write(minigolf.online.Json.object().put("port", server.port())
                .put("database", server.database()).put("courses", catalog.names().size())
                .put("restoredRooms", server.restoredRooms())));
        out.flush();
        server.join();
        return 0;
    }
}
