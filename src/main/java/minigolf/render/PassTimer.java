package minigolf.render;

import java.util.LinkedHashMap;
import java.util.Map;

import static org.lwjgl.opengl.GL11.glFinish;

/**
 * Wall time per render pass for the benchmark's breakdown: each {@link #mark} waits for the GL to
 * finish (glFinish) and charges the time since the previous mark to a named pass. The waits stall
 * the pipeline, so a timed frame is slower than an untimed one; when off, marks cost nothing.
 */
public final class PassTimer {
    private final Map<String, Long> nanos = new LinkedHashMap<>();
    private boolean on;
    private long last;

    public void setOn(boolean on) {
        this.on = on;
    }

    public boolean on() {
        return on;
    }

    /** Starts a frame's timing (finishes earlier GL work first, so it is not charged to the first pass). */
    void start() {
        if (!on) return;
        glFinish();
        last = System.nanoTime();
    }

    /** Charges the GL work since the last mark to {@code pass}. */
    void mark(String pass) {
        if (!on) return;
        glFinish();
        long now = System.nanoTime();
        nanos.merge(pass, now - last, Long::sum);
        last = now;
    }

    public void reset() {
        nanos.clear();
    }

    /** Milliseconds per frame for each pass, over {@code frames} frames, in the order first seen. */
    public Map<String, Double> millisPerFrame(int frames) {
        Map<String, Double> out = new LinkedHashMap<>();
        nanos.forEach((k, v) -> out.put(k, Math.round(v / 1e4 / frames) / 100.0));
        return out;
    }
}
