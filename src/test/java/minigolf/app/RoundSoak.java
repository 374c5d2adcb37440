package minigolf.app;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.management.ObjectName;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.game.SettingsStore;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.MemoryUtil;

import static org.lwjgl.opengl.GL33.*;

/**
 * A long bot round in the real game window, for memory across holes (issue 29): plays ROUND with
 * bots again and again (the card between holes for 30 frames, a new round after the final card)
 * and prints one line per interval: minutes, holes played, the process's resident memory, the Java
 * heap after a collection, the JVM's tracked native memory (with -XX:NativeMemoryTracking=summary),
 * the GL objects alive (names answered by glIsBuffer, glIsTexture, ...) and, with
 * -Dorg.lwjgl.util.DebugAllocator=true, the bytes LWJGL's allocator holds. A tool, not a test:
 *
 * <pre>
 * java -XX:NativeMemoryTracking=summary -cp CLASSPATH minigolf.app.RoundSoak MINUTES ROUND.json [INTERVAL_S] [WIDTHxHEIGHT (640x480)]
 * </pre>
 */
public final class RoundSoak {
    /** Passes of the loop the card between holes is shown before the next hole (as a scripted run's 30 frames). */
    static final int CARD_PASSES = 30;

    private RoundSoak() {
    }

    public static void main(String[] args) throws Exception {
        double minutes = Double.parseDouble(args[0]);
        Path roundFile = Path.of(args[1]);
        double interval = args.length > 2 ? Double.parseDouble(args[2]) : 60;
        String size = args.length > 3 ? args[3] : "640x480";
        Round round = RoundLoader.load(roundFile);
        Path config = Files.createTempDirectory("minigolf-soak");
        int w = Integer.parseInt(size.split("x")[0]), h = Integer.parseInt(size.split("x")[1]);
        // A modest window and frame rate: the soak measures memory across holes, not speed.
        Files.writeString(config.resolve("settings.json"), "{\"vsync\": false, \"frameLimit\": 20, \"windowWidth\": " + w
                + ", \"windowHeight\": " + h + "}");
        List<Player> players = List.of(Player.bot("Bot (planner)", "planner"), Player.bot("Bot 2 (straight)", "straight"));
        GameApp.Options options = new GameApp.Options(null, null, 0, players, List.of(), 4, new SettingsStore(config), true, false);
        GameApp app = new GameApp(round.hole(0).world(), options);
        app.playRound(round);
        long start = System.nanoTime();
        double[] nextReport = {0};
        int[] holes = {0}, cardPasses = {0}, rounds = {1};
        Object[] lastGame = {null};
        System.out.println("minutes,holes,rounds,rssMB,heapMB,nmtCommittedMB,glBuffers,glTextures,glVertexArrays,glFramebuffers,"
                + "glRenderbuffers,glPrograms,glShaders,lwjglDebugBytes,heapCommittedMB");
        app.onLoopPass((pass, window) -> {
            double t = (System.nanoTime() - start) / 60e9;
            if (app.game() != null && app.game() != lastGame[0]) { // a new hole's game
                lastGame[0] = app.game();
                holes[0]++;
            }
            if (app.screen() == app.screens().roundCard() && app.roundGame() != null) {
                if (++cardPasses[0] >= CARD_PASSES) {
                    cardPasses[0] = 0;
                    if (app.roundGame().isOver()) {
                        rounds[0]++;
                        app.startGame(players); // the same round again, from hole 1
                    } else if (app.play().nextHole()) { // what the card's "Next hole" does
                        app.scene().resetCamera();
                        app.setScreen(app.screens().playing());
                    }
                }
            }
            if (t >= nextReport[0]) {
                nextReport[0] += interval / 60;
                System.out.println(report(t, holes[0], rounds[0]));
                System.out.flush();
            }
            if (t >= minutes) window.requestClose();
        });
        app.run(); // the last interval's line is the last report (GL is gone after the window closes)
    }

    private static String report(double minutes, int holes, int rounds) {
        System.gc();
        long heap = Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory();
        return String.format(Locale.ROOT, "%.2f,%d,%d,%.1f,%.1f,%.1f,%s,%d,%.1f", minutes, holes, rounds, rssKb() / 1024.0,
                heap / 1048576.0, nmtCommittedKb() / 1024.0, glObjects(), lwjglBytes(),
                Runtime.getRuntime().totalMemory() / 1048576.0);
    }

    /** VmRSS from /proc/self/status, in KiB (0 where there is none). */
    static long rssKb() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmRSS:")) return Long.parseLong(line.replaceAll("[^0-9]", ""));
            }
        } catch (IOException | RuntimeException e) {
            return 0;
        }
        return 0;
    }

    /** The committed total of the JVM's native memory tracking (KiB), or -1 when tracking is off. */
    static long nmtCommittedKb() {
        try {
            String out = (String) ManagementFactory.getPlatformMBeanServer().invoke(
                    new ObjectName("com.sun.management:type=DiagnosticCommand"), "vmNativeMemory",
                    new Object[]{new String[]{"summary"}}, new String[]{String[].class.getName()});
            for (String line : out.split("\n")) {
                int i = line.indexOf("Total: reserved=");
                if (i >= 0) {
                    String c = line.substring(line.indexOf("committed=") + 10);
                    return Long.parseLong(c.replaceAll("KB.*", "").trim());
                }
            }
        } catch (Exception e) {
            return -1;
        }
        return -1;
    }

    /** GL names alive, per kind, among the first 20,000 (the game makes a few hundred). */
    static String glObjects() {
        int buffers = 0, textures = 0, arrays = 0, framebuffers = 0, renderbuffers = 0, programs = 0, shaders = 0;
        for (int id = 1; id <= 20_000; id++) {
            if (glIsBuffer(id)) buffers++;
            if (glIsTexture(id)) textures++;
            if (glIsVertexArray(id)) arrays++;
            if (glIsFramebuffer(id)) framebuffers++;
            if (glIsRenderbuffer(id)) renderbuffers++;
            if (glIsProgram(id)) programs++;
            if (glIsShader(id)) shaders++;
        }
        glGetError();
        return buffers + "," + textures + "," + arrays + "," + framebuffers + "," + renderbuffers + "," + programs + "," + shaders;
    }

    /** Bytes LWJGL's allocator holds, when its debug allocator is on (-Dorg.lwjgl.util.DebugAllocator=true), else -1. */
    static long lwjglBytes() {
        if (!Configuration.DEBUG_MEMORY_ALLOCATOR.get(false)) return -1;
        long[] total = {0};
        MemoryUtil.memReport((address, memory, threadId, threadName, stacktrace) -> total[0] += memory);
        return total[0];
    }
}
