package minigolf.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import minigolf.game.PlayerStatus;
import minigolf.online.RoomEvent;
import minigolf.online.client.LoadBench;
import minigolf.online.client.OnlineClient;
import minigolf.online.store.GameStore;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

@Command(name = "bench-server",
        description = "Starts a game server in a process of its own (SQLite in a scratch folder) and plays ROOMS rooms of "
                + "SEATS headless bot players against it on the loopback address, all connected at once; prints the shot "
                + "latency (sent to stroke received), the server's peak memory and CPU, the load average, and checks "
                + "every room's stored strokes against its players' cards (docs/online.md, Benchmarks).")
final class BenchServerCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--rooms", paramLabel = "N", description = "Rooms (default: ${DEFAULT-VALUE}).")
    int rooms = 250;

    @Option(names = "--seats", paramLabel = "N", description = "Players per room, 1 to 4 (default: ${DEFAULT-VALUE}).")
    int seats = 4;

    @Option(names = "--course", paramLabel = "NAME", description = "The course or round every room plays (default: ${DEFAULT-VALUE}).")
    String course = "meadowbrook-9";

    @Option(names = "--bot", paramLabel = "LEVEL", description = "The players' bot (default: ${DEFAULT-VALUE}: no search, so the "
            + "clients' CPU stays small).")
    String bot = "straight";

    @Option(names = "--think", paramLabel = "SECONDS", description = "Each player's pause before a shot, as a person "
            + "aims (default: ${DEFAULT-VALUE}).")
    double think = 2;

    @Option(names = "--think-spread", paramLabel = "FRACTION", description = "Each pause is drawn uniformly within "
            + "think × (1 ± FRACTION), 0 to 1 (default: ${DEFAULT-VALUE}; 0: every room shoots in lock-step, since all play "
            + "the same course with the same bot).")
    double thinkSpread = 0.5;

    @Option(names = "--seed", paramLabel = "N", description = "Seed of the pauses (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Option(names = "--server-heap", paramLabel = "SIZE", description = "The server's -Xmx (default: ${DEFAULT-VALUE}).")
    String serverHeap = "768m";

    @Option(names = "--timeout", paramLabel = "SECONDS", description = "Give up after this long (default: ${DEFAULT-VALUE}).")
    double timeout = 1800;

    @Option(names = "--strokes", paramLabel = "FILE", description = "Also write every timed stroke to FILE as CSV: player, "
            + "event number, hole, when it was sent (s), its latency and its arrival at the room's other players (ms) (default: none).")
    Path strokesFile;

    @Override
    public Integer call() throws Exception {
        if (rooms < 1 || rooms > 5000) throw new UserError("--rooms: must be 1 to 5000");
        if (seats < 1 || seats > 4) throw new UserError("--seats: must be 1 to 4");
        if (!(think >= 0 && think <= 60)) throw new UserError("--think: must be 0 to 60 s");
        if (!(thinkSpread >= 0 && thinkSpread <= 1)) throw new UserError("--think-spread: must be 0 to 1");
        if (!serverHeap.matches("[0-9]+[mMgG]")) throw new UserError("--server-heap: a size such as 768m or 1g");
        if (strokesFile != null) {
            Path folder = strokesFile.toAbsolutePath().getParent();
            if (folder == null || !Files.isDirectory(folder)) throw new UserError("--strokes: no folder " + folder);
            if (Files.isDirectory(strokesFile)) throw new UserError("--strokes: " + strokesFile + " is a folder");
        }
        Path scratch = Files.createTempDirectory("minigolf-bench-server");
        Path db = scratch.resolve("bench.db");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + serverHeap, "-cp", System.getProperty("java.class.path"), "minigolf.Main", "server", "--port", "0",
                "--host", "127.0.0.1", "--db", db.toString(), "--connections-per-address", String.valueOf(rooms * seats + 100),
                "--rooms-per-address", String.valueOf(rooms + 10), "--messages-per-second", "100"));
        Process server = new ProcessBuilder(cmd).redirectError(scratch.resolve("server.err").toFile()).start();
        var err = spec.commandLine().getErr();
        try {
            BufferedReader r = new BufferedReader(new InputStreamReader(server.getInputStream(), StandardCharsets.UTF_8));
            String first = r.readLine();
            if (first == null) throw new UserError("the server did not start: " + Files.readString(scratch.resolve("server.err")));
            int port = minigolf.online.Json.parse(first).get("port").asInt();
            String loadBefore = loadAverage();
            double cpuBefore = LoadBench.cpuSeconds(server.pid());
            LoadBench.Result res = LoadBench.run(OnlineClient.uri("127.0.0.1:" + port), course, rooms, seats, bot,
                    Math.round(think * 1000), thinkSpread, seed, timeout, line -> {
                        err.println("bench-server: " + line + ", load " + loadAverage());
                        err.flush();
                    });
            for (String f : res.failures().subList(0, Math.min(20, res.failures().size()))) err.println("bench-server: " + f);
            if (strokesFile != null) writeStrokes(strokesFile, res.strokes());
            double serverCpu = LoadBench.cpuSeconds(server.pid()) - cpuBefore;
            double rss = LoadBench.peakRssMb(server.pid());
            String loadAfter = loadAverage();
            server.destroy(); // SIGTERM: the server closes its database cleanly
            server.waitFor(30, TimeUnit.SECONDS);
            Check check = check(db, res.cards(), seats);
            // The server's own report of strokes that went out a second or more after their shot arrived (where the time went).
            List<String> slow = Files.readAllLines(scratch.resolve("server.err"), StandardCharsets.UTF_8).stream()
                    .filter(l -> l.contains("went out")).toList();
            for (String l : slow.subList(0, Math.min(20, slow.size()))) err.println("bench-server: " + l);
            ObjectNode out = minigolf.online.Json.object();
            out.put("players", res.players()).put("peakConnected", res.peakConnected()).put("rooms", rooms)
                    .put("roomsFinished", res.roomsFinished()).put("course", course).put("bot", bot).put("thinkSeconds", think).put("thinkSpread", thinkSpread).put("seed", seed)
                    .put("shots", res.shots()).put("seconds", Math.round(res.seconds() * 10) / 10.0)
                    .put("p50Ms", round(res.percentileMs(50))).put("p99Ms", round(res.percentileMs(99)))
                    .put("maxMs", round(res.percentileMs(100))).put("reconnects", res.reconnects()).put("serverPeakRssMb", Math.round(rss))
                    .put("serverCpuSeconds", round(serverCpu)).put("serverSlowStrokes", slow.size()).put("storedStrokes", check.stored)
                    .put("lostOrDuplicated", check.problems.size()).put("loadAverageBefore", loadBefore)
                    .put("loadAverageAfter", loadAfter).put("cores", Runtime.getRuntime().availableProcessors());
            if (!res.failures().isEmpty()) out.put("failures", res.failures().size()).put("firstFailure", res.failures().get(0));
            if (!check.problems.isEmpty()) out.put("firstProblem", check.problems.get(0));
            spec.commandLine().getOut().println(minigolf.online.Json.write(out));
            return res.failures().isEmpty() && check.problems.isEmpty() && res.roomsFinished() == rooms ? 0 : 1;
        } finally {
            if (server.isAlive()) server.destroyForcibly();
            try (var files = Files.walk(scratch)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    private static void writeStrokes(Path file, List<LoadBench.StrokeTime> strokes) throws IOException {
        StringBuilder b = new StringBuilder(LoadBench.StrokeTime.CSV_HEADER).append('\n');
        for (LoadBench.StrokeTime t : strokes) b.append(t.csv()).append('\n');
        minigolf.io.AtomicFile.write(file, b.toString().getBytes(StandardCharsets.UTF_8));
    }

    private record Check(int stored, List<String> problems) {
    }

    /** Every room's events numbered 1..n once each, and per seat and hole equal to what its players' cards say. */
    private static Check check(Path db, Map<String, JsonNode> cards, int seats) throws Exception {
        List<String> problems = new ArrayList<>();
        int stored = 0;
        try (GameStore store = GameStore.open(db.toString())) {
            for (Map.Entry<String, JsonNode> e : cards.entrySet()) {
                if (!e.getKey().endsWith("/0")) continue;
                String room = e.getKey().substring(0, e.getKey().indexOf('/'));
                JsonNode card = e.getValue();
                List<String> events = store.events(room);
                int holes = card.get("players").get(0).get("strokes").size();
                int[][] score = new int[seats][holes];
                for (int i = 0; i < events.size(); i++) {
                    RoomEvent ev = RoomEvent.parse(minigolf.online.Json.parse(events.get(i)), seats);
                    if (ev.seq() != i + 1) problems.add(room + ": event " + (i + 1) + " is numbered " + ev.seq());
                    score[ev.seat()][ev.hole()] = ev.after().status() == PlayerStatus.PICKED_UP
                            ? minigolf.game.Game.DEFAULT_STROKE_LIMIT + 1 : ev.after().total();
                    if (ev.stroke() != null) stored++;
                }
                for (int s = 0; s < seats; s++) {
                    for (int h = 0; h < holes; h++) {
                        int onCard = card.get("players").get(s).get("strokes").get(h).asInt();
                        if (onCard != score[s][h]) problems.add(room + " seat " + s + " hole " + (h + 1) + ": card " + onCard
                                + ", stored " + score[s][h]);
                    }
                }
                for (int s = 1; s < seats; s++) {
                    JsonNode other = cards.get(room + "/" + s);
                    if (other != null && !other.equals(card)) problems.add(room + ": seat " + s + "'s card differs from seat 0's");
                }
            }
        }
        return new Check(stored, problems);
    }

    private static double round(double v) {
        return Math.round(v * 10) / 10.0;
    }

    private static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }
}
