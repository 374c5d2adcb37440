package minigolf.online.client;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import minigolf.online.Json;

/**
 * The load benchmark's players (docs/online.md, "Benchmarks"): {@code rooms} rooms of
 * {@code seats} headless bot players each, all connected at once, each room playing one round on
 * a server. Every shot is timed from the moment it is sent to the moment its stroke comes back.
 */
public final class LoadBench {
    /** The measured figures. */
    public record Result(int players, int peakConnected, int roomsFinished, long shots, long[] latencyNanos,
                         List<String> failures, Map<String, JsonNode> cards, double seconds, int reconnects,
                         List<StrokeTime> strokes) {
        public double percentileMs(double p) {
            if (latencyNanos.length == 0) return Double.NaN;
            long[] sorted = latencyNanos.clone();
            Arrays.sort(sorted);
            int i = (int) Math.ceil(p / 100 * sorted.length) - 1;
            return sorted[Math.max(0, Math.min(sorted.length - 1, i))] / 1e6;
        }
    }

    /**
     * One timed stroke: the player ({@code P<room>-<seat>}), the room's event number and hole (from 0),
     * when the shot was sent (seconds since the benchmark began), its latency, and when the same
     * event arrived at the room's other players (the earliest and the latest, ms after the shot was
     * sent; NaN with one seat). A delay before the server broadcast reaches every seat of the room;
     * one that only the shooter sees is its own connection's.
     */
    public record StrokeTime(String player, long seq, int hole, double sentSeconds, double latencyMs,
                             double othersFirstMs, double othersLastMs) {
        /** The CSV header of {@link #csv()}. */
        public static final String CSV_HEADER = "player,seq,hole,sentSeconds,latencyMs,othersFirstMs,othersLastMs";

        public String csv() {
            return String.format(java.util.Locale.ROOT, "%s,%d,%d,%.3f,%.3f,%.3f,%.3f", player, seq, hole,
                    sentSeconds, latencyMs, othersFirstMs, othersLastMs);
        }
    }

    private LoadBench() {
    }

    /**
     * Runs the rooms to the end (or until {@code timeoutSeconds}) and returns what was measured;
     * {@code progress} gets a line now and then.
     */
    public static Result run(URI server, String course, int rooms, int seats, String bot, long thinkMillis,
                             double timeoutSeconds, Consumer<String> progress) throws InterruptedException {
        return run(server, course, rooms, seats, bot, thinkMillis, 0, 0, timeoutSeconds, progress);
    }

    /**
     * As {@link #run(URI, String, int, int, String, long, double, Consumer)}, each pause before a shot drawn
     * within {@code thinkMillis × (1 ± thinkSpread)} from {@code seed} (one stream per player).
     */
    public static Result run(URI server, String course, int rooms, int seats, String bot, long thinkMillis, double thinkSpread,
                             long seed, double timeoutSeconds, Consumer<String> progress) throws InterruptedException {
        List<Thread> threads = new ArrayList<>();
        List<String> failures = java.util.Collections.synchronizedList(new ArrayList<>());
        Map<String, JsonNode> cards = new ConcurrentHashMap<>();
        List<long[]> latencies = java.util.Collections.synchronizedList(new ArrayList<>());
        Map<String, HeadlessPlayer> playing = new ConcurrentHashMap<>();
        Map<String, Timer> timers = new ConcurrentHashMap<>();
        AtomicInteger connected = new AtomicInteger(), peak = new AtomicInteger(), reconnects = new AtomicInteger();
        CountDownLatch done = new CountDownLatch(rooms * seats);
        // Every room's last player waits until all the others are connected and seated: then every round starts at
        // once, with all the players connected together.
        CountDownLatch others = new CountDownLatch(rooms * Math.max(0, seats - 1));
        CountDownLatch gate = new CountDownLatch(1);
        long start = System.nanoTime();
        for (int r = 0; r < rooms; r++) {
            CountDownLatch code = new CountDownLatch(1);
            String[] roomCode = new String[1];
            for (int s = 0; s < seats; s++) {
                int seat = s;
                String name = "P" + r + "-" + s;
                Thread t = new Thread(() -> {
                    Timer timer = new Timer(() -> {
                        peak.accumulateAndGet(connected.incrementAndGet(), Math::max);
                        if (seat < seats - 1) others.countDown();
                    });
                    timers.put(name, timer);
                    try {
                        if (seat > 0 && !code.await(120, TimeUnit.SECONDS)) throw new IllegalStateException("no room code");
                        HeadlessPlayer.Options o = new HeadlessPlayer.Options(server, seat == 0 ? course : null, seats, List.of(),
                                false, seat == 0 ? null : roomCode[0], name, bot, null, thinkMillis);
                        HeadlessPlayer player = new HeadlessPlayer(o, line -> {
                            ObjectNode m = parse(line);
                            if (m != null && m.has("room") && !m.has("players")) {
                                roomCode[0] = m.get("room").asText();
                                code.countDown();
                            } else if (m != null && m.has("players")) {
                                cards.put(m.get("room").asText() + "/" + seat, m);
                            }
                        }, line -> {
                            if (line.endsWith("; reconnecting")) reconnects.incrementAndGet();
                        }, timer);
                        if (seat == seats - 1 && seats > 1) player.joinAfter(gate);
                        player.thinkSpread(thinkSpread, seed * 1_000_003L + name.hashCode());
                        playing.put(name, player);
                        player.run();
                        playing.remove(name);
                    } catch (Exception | Error e) {
                        failures.add(name + ": " + e.getMessage());
                        code.countDown();
                    } finally {
                        if (timer.wasSeated()) connected.decrementAndGet();
                        latencies.add(timer.latencies());
                        done.countDown();
                    }
                }, "bench-" + name);
                t.setDaemon(true);
                threads.add(t);
                t.start();
            }
            // Let the room's creator get its code before the next room's players start.
            code.await(120, TimeUnit.SECONDS);
        }
        others.await(600, TimeUnit.SECONDS);
        progress.accept(String.format(java.util.Locale.ROOT, "%.0f s: %d connected; the last players join now",
                (System.nanoTime() - start) / 1e9, connected.get()));
        gate.countDown();
        long deadline = start + (long) (timeoutSeconds * 1e9);
        while (!done.await(10, TimeUnit.SECONDS)) {
            progress.accept(String.format(java.util.Locale.ROOT, "%.0f s: %d connected, %d rooms' cards in",
                    (System.nanoTime() - start) / 1e9, connected.get(), cards.size() / Math.max(1, seats)));
            if (System.nanoTime() > deadline) {
                failures.add("timed out after " + timeoutSeconds + " s with " + done.getCount() + " players still playing");
                playing.forEach((n, p) -> failures.add(n + " still playing: " + p.recentMessages()));
                break;
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        long total = 0;
        for (long[] l : latencies) total += l.length;
        long[] all = new long[(int) total];
        int k = 0;
        synchronized (latencies) {
            for (long[] l : latencies) for (long v : l) all[k++] = v;
        }
        int finished = (int) cards.keySet().stream().map(c -> c.substring(0, c.indexOf('/'))).distinct().count();
        return new Result(rooms * seats, peak.get(), finished, k, Arrays.copyOf(all, k), List.copyOf(failures), cards, seconds,
                reconnects.get(), strokeTimes(timers, rooms, seats, start));
    }

    /** Every timed stroke, with its event's arrival at the room's other players; in the order the shots were sent. */
    private static List<StrokeTime> strokeTimes(Map<String, Timer> timers, int rooms, int seats, long start) {
        List<StrokeTime> out = new ArrayList<>();
        for (int r = 0; r < rooms; r++) {
            for (int s = 0; s < seats; s++) {
                Timer t = timers.get("P" + r + "-" + s);
                if (t == null) continue;
                for (long[] st : t.strokes()) {
                    long seq = st[0], sent = st[2];
                    double first = Double.NaN, last = Double.NaN;
                    for (int o = 0; o < seats; o++) {
                        Timer other = o == s ? null : timers.get("P" + r + "-" + o);
                        long at = other == null ? Timer.NONE : other.arrival(seq);
                        if (at == Timer.NONE) continue;
                        double ms = (at - sent) / 1e6;
                        first = Double.isNaN(first) ? ms : Math.min(first, ms);
                        last = Double.isNaN(last) ? ms : Math.max(last, ms);
                    }
                    out.add(new StrokeTime("P" + r + "-" + s, seq, (int) st[1], (sent - start) / 1e9, st[3] / 1e6, first, last));
                }
            }
        }
        out.sort(java.util.Comparator.comparingDouble(StrokeTime::sentSeconds));
        return out;
    }

    private static ObjectNode parse(String line) {
        try {
            return Json.parse(line);
        } catch (minigolf.online.ProtocolException e) {
            return null;
        }
    }

    /** One player's shot timings: sent at seq n, received as event n + 1 of the same seat; and when each event arrived. */
    private static final class Timer implements HeadlessPlayer.Timing {
        private final Runnable onSeated;
        private boolean seated;
        /** No arrival recorded (System.nanoTime may be negative, so not -1). */
        static final long NONE = Long.MIN_VALUE;
        private long sentSeq = -1, sentAt;
        private int sentSeat = -1;

        Timer(Runnable onSeated) {
            this.onSeated = onSeated;
        }

        @Override
        public synchronized void seated() {
            if (!seated) onSeated.run();
            seated = true;
        }

        synchronized boolean wasSeated() {
            return seated;
        }
        private long[] lat = new long[64];
        private int n;

        @Override
        public synchronized void shotSent(long seq, int seat, long nanos) {
            sentSeq = seq;
            sentSeat = seat;
            sentAt = nanos;
        }

        /** Every timed stroke: {seq, hole, sent at, latency}. */
        private final List<long[]> strokes = new ArrayList<>();
        /** When each event (by its number) arrived at this player; -1 where none did. */
        private long[] arrivals = none(64);

        @Override
        public synchronized void strokeReceived(long seq, int seat, int hole, long nanos) {
            if (seq >= 0 && seq < 1_000_000) {
                if (seq >= arrivals.length) {
                    int old = arrivals.length;
                    arrivals = Arrays.copyOf(arrivals, (int) Math.max(seq + 1, 2L * old));
                    Arrays.fill(arrivals, old, arrivals.length, NONE);
                }
                if (arrivals[(int) seq] == NONE) arrivals[(int) seq] = nanos;
            }
            if (sentSeq >= 0 && seq == sentSeq + 1 && seat == sentSeat) {
                if (n == lat.length) lat = Arrays.copyOf(lat, n * 2);
                lat[n++] = nanos - sentAt;
                strokes.add(new long[]{seq, hole, sentAt, nanos - sentAt});
                sentSeq = -1;
            }
        }

        synchronized long[] latencies() {
            return Arrays.copyOf(lat, n);
        }

        synchronized List<long[]> strokes() {
            return List.copyOf(strokes);
        }

        /** When event {@code seq} arrived, or {@link #NONE}. */
        synchronized long arrival(long seq) {
            return seq >= 0 && seq < arrivals.length ? arrivals[(int) seq] : NONE;
        }

        private static long[] none(int n) {
            long[] a = new long[n];
            Arrays.fill(a, NONE);
            return a;
        }
    }

    /** The server's peak resident memory (VmHWM) in MB, from /proc; NaN elsewhere. */
    public static double peakRssMb(long pid) {
        try {
            for (String line : java.nio.file.Files.readAllLines(Path.of("/proc", String.valueOf(pid), "status"))) {
                if (line.startsWith("VmHWM:")) return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1024.0;
            }
        } catch (java.io.IOException | NumberFormatException e) {
            // not Linux, or the process is gone
        }
        return Double.NaN;
    }

    /** The process's CPU seconds so far (user + system), from /proc; NaN elsewhere. */
    public static double cpuSeconds(long pid) {
        try {
            String stat = java.nio.file.Files.readString(Path.of("/proc", String.valueOf(pid), "stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return (Long.parseLong(f[11]) + Long.parseLong(f[12])) / 100.0;
        } catch (java.io.IOException | RuntimeException e) {
            return Double.NaN;
        }
    }
}
