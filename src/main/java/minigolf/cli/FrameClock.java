package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import minigolf.render.Window;

import static org.lwjgl.opengl.GL11.GL_RENDERER;
import static org.lwjgl.opengl.GL11.glGetString;

/**
 * Times the game loop from its passes (GameApp's loop hook, called at the start of each pass): wall
 * and process CPU time from the pass after the warm-up to the last pass seen, so every timed frame
 * was drawn and swapped. CPU time counts the rasteriser's threads too (llvmpipe).
 */
final class FrameClock {
    private final int warmUp;
    private long startNanos, lastNanos, startCpu, lastCpu;
    private int timedFrames;
    private String renderer = "";
    private int width, height;

    FrameClock(int warmUp) {
        this.warmUp = Math.max(1, warmUp);
    }

    void pass(int pass, Window window) {
        if (pass < warmUp) return;
        long now = System.nanoTime(), cpu = processCpuMillis();
        if (pass == warmUp) {
            startNanos = now;
            startCpu = cpu;
            renderer = glGetString(GL_RENDERER);
        }
        lastNanos = now;
        lastCpu = cpu;
        timedFrames = pass - warmUp;
        width = window.framebufferWidth();
        height = window.framebufferHeight();
    }

    String json(String course) {
        ObjectNode out = Json.object();
        out.put("frames", timedFrames);
        if (timedFrames > 0) {
            double ms = (lastNanos - startNanos) / 1e6 / timedFrames;
            out.put("msPerFrame", Math.round(ms * 100) / 100.0);
            out.put("fps", Math.round(10000 / ms) / 10.0);
            if (startCpu >= 0 && lastCpu >= 0) out.put("cpuMsPerFrame", Math.round((lastCpu - startCpu) * 10.0 / timedFrames) / 10.0);
        }
        out.put("size", width + "x" + height);
        out.put("course", course);
        out.put("renderer", renderer);
        return Json.write(out);
    }

    /** User + system CPU time of this process in ms from /proc/self/stat (Linux, 100 ticks a second), or -1. */
    static long processCpuMillis() {
        try {
            String stat = java.nio.file.Files.readString(java.nio.file.Path.of("/proc/self/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return (Long.parseLong(f[11]) + Long.parseLong(f[12])) * 10;
        } catch (java.io.IOException | RuntimeException e) {
            return -1;
        }
    }
}
