package minigolf.render;

import java.util.LinkedHashMap;
import java.util.Map;

import static org.lwjgl.opengl.GL11.glFinish;
import static org.lwjgl.opengl.GL15.*;
import static org.lwjgl.opengl.GL30.GL_PRIMITIVES_GENERATED;

/**
 * Wall time per render pass for the benchmark's breakdown: each {@link #mark} waits for the GL to
 * finish (glFinish) and charges the time since the previous mark to a named pass, with the triangles
 * the pass sent down the pipeline (a GL_PRIMITIVES_GENERATED query: llvmpipe's vertex and set-up
 * work runs on the calling thread, so triangles cost wall time as pixels do). The waits stall the
 * pipeline, so a timed frame is slower than an untimed one; when off, marks cost nothing.
 */
public final class PassTimer {
    private final Map<String, Long> nanos = new LinkedHashMap<>();
    private final Map<String, Long> triangles = new LinkedHashMap<>();
    private boolean on;
    private long last;
    private int query;
    /** Whether the query is counting (from a start or mark to the next; ended when the timer is turned off). */
    private boolean counting;

    public void setOn(boolean on) {
        this.on = on;
        if (!on && counting) {
            glEndQuery(GL_PRIMITIVES_GENERATED);
            counting = false;
        }
    }

    public boolean on() {
        return on;
    }

    /** Starts a frame's timing (finishes earlier GL work first, so it is not charged to the first pass). */
    void start() {
        if (!on) return;
        glFinish();
        if (query == 0) query = glGenQueries();
        if (counting) glEndQuery(GL_PRIMITIVES_GENERATED); // what came between frames is no pass's
        glBeginQuery(GL_PRIMITIVES_GENERATED, query);
        counting = true;
        last = System.nanoTime();
    }

    /** Charges the GL work since the last mark to {@code pass}. */
    void mark(String pass) {
        if (!on) return;
        glFinish();
        long now = System.nanoTime();
        nanos.merge(pass, now - last, Long::sum);
        if (counting) {
            glEndQuery(GL_PRIMITIVES_GENERATED);
            triangles.merge(pass, (long) glGetQueryObjecti(query, GL_QUERY_RESULT), Long::sum);
        }
        glBeginQuery(GL_PRIMITIVES_GENERATED, query);
        counting = true;
        last = System.nanoTime();
    }

    public void reset() {
        nanos.clear();
        triangles.clear();
    }

    /** Triangles per frame sent by each pass (clipped or not), over {@code frames} frames, in the order first seen. */
    public Map<String, Long> trianglesPerFrame(int frames) {
        Map<String, Long> out = new LinkedHashMap<>();
        triangles.forEach((k, v) -> out.put(k, Math.round((double) v / frames)));
        return out;
    }

    /** Milliseconds per frame for each pass, over {@code frames} frames, in the order first seen. */
    public Map<String, Double> millisPerFrame(int frames) {
        Map<String, Double> out = new LinkedHashMap<>();
        nanos.forEach((k, v) -> out.put(k, Math.round(v / 1e4 / frames) / 100.0));
        return out;
    }
}
