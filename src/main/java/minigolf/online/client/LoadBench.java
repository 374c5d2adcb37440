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
                         List<String> failures, Map<String, JsonNode> cards, double seconds, int reconnects) {
        public double percentileMs(double p) {
            if (latencyNanos.length == 0) return Double.NaN;
            long[] sorted = latencyNanos.clone();
            Arrays.sort(sorted);
            int i = (int) Math.ceil(p / 100 * sorted.length) - 1;
            return sorted[Math.max(0, Math.min(sorted.length - 1, i))] / 1e6;
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
                reconnects.get());
    }

    private static ObjectNode parse(String line) {
        try {
            return Json.parse(line);
        } catch (minigolf.online.ProtocolException e) {
            return null;
        }
    }

    /** One player's shot timings: sent at seq n, received as event n + 1 of the same seat. */
    private static final class Timer implements HeadlessPlayer.Timing {
        private final Runnable onSeated;
        private boolean seated;
        private long sentSeq = -1, sentAt;

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
        public synchronized void shotSent(long seq, long nanos) {
            sentSeq = seq;
            sentAt = nanos;
        }

        @Override
        public synchronized void strokeReceived(long seq, int seat, long nanos) {
            if (sentSeq >= 0 && seq == sentSeq + 1) {
                if (n == lat.length) lat = Arrays.copyOf(lat, n * 2);
                lat[n++] = nanos - sentAt;
                sentSeq = -1;
            }
        }

        synchronized long[] latencies() {
            return Arrays.copyOf(lat, n);
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
