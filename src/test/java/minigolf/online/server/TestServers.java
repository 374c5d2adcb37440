package minigolf.online.server;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;

/** Servers for tests: on a free port of the loopback address, the project's courses, a given database. */
final class TestServers {
    static final Path COURSES = Path.of(System.getProperty("minigolf.projectDir", "."), "courses");
    private static CourseCatalog catalog;

    private TestServers() {
    }

    static synchronized CourseCatalog catalog() {
        if (catalog == null) catalog = CourseCatalog.load(COURSES, new PrintWriter(new StringWriter()));
        return catalog;
    }

    static ServerOptions options(String db) {
        return ServerOptions.defaults(0, db, COURSES).withHost("127.0.0.1").withAddressLimits(100, 100).withRate(1000, 3000);
    }

    static GameServer start(ServerOptions o, StringWriter log) throws Exception {
        return GameServer.start(o, catalog(), new PrintWriter(log, true));
    }

    static GameServer start(String db) throws Exception {
        return start(options(db), new StringWriter());
    }
}
