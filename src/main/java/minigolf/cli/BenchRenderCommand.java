package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.course.CourseException;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.physics.World;
import minigolf.render.Offscreen;
import minigolf.render.OrbitCamera;
import minigolf.render.RenderQuality;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

import static org.lwjgl.opengl.GL11.*;

@Command(name = "bench-render",
        description = "Renders N frames of the full scene off-screen (after a warm-up) and prints milliseconds per frame;"
                + " given a round file, does so for every hole and can write a table (--table).")
final class BenchRenderCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE|ROUND", description = "A course file, or a round file (every hole is timed).")
    Path course;

    @Option(names = "--table", paramLabel = "FILE.md",
            description = "Also write a Markdown table of the holes' times, with the load average and the commit (default: none).")
    Path table;

    @Option(names = "--frames", paramLabel = "N", description = "Frames to time after the warm-up (default: ${DEFAULT-VALUE}).")
    int frames = 200;

    @Option(names = "--size", paramLabel = "WxH", description = "Frame size in pixels (default: ${DEFAULT-VALUE}).")
    String size = "1280x720";

    @Option(names = "--samples", paramLabel = "N", description = "Multisampling, samples per pixel (default: the quality's, as the game window's; 0 off).")
    Integer samples;

    @Option(names = "--quality", paramLabel = "Q",
            description = "auto (as the game picks it from GL_RENDERER), high (real GPUs) or software (llvmpipe) (default: ${DEFAULT-VALUE}).")
    String quality = "auto";

    @Option(names = "--water-scale", paramLabel = "S", description = "The water targets' size as a fraction of the frame's, 0..1 (default: the quality's).")
    Float waterScale;

    @Option(names = "--no-reflections", description = "Plain water colours instead of reflection and refraction (default: off).")
    boolean noReflections;

    @Option(names = "--no-shadows", description = "No sun shadows (default: off).")
    boolean noShadows;

    @Option(names = "--fxaa", description = "The FXAA pass (only for frames without multisampling; default: off, as in the game).")
    boolean fxaa;

    @Option(names = "--breakdown", description = "Also time each pass (glFinish after each; run separately from the untimed frames; default: off).")
    boolean breakdown;

    @Override
    public Integer call() {
        if (frames < 1) throw new UserError("--frames: must be at least 1, got " + frames);
        if (samples != null && (samples < 0 || samples > 16)) throw new UserError("--samples: must be 0 to 16, got " + samples);
        if (waterScale != null && !(waterScale >= 0.1f && waterScale <= 1f)) throw new UserError("--water-scale: must be 0.1 to 1, got " + waterScale);
        RenderQuality chosen = RenderQuality.named(quality);
        if (chosen == null && !quality.equalsIgnoreCase("auto")) {
            throw new UserError("--quality: must be auto, high or software, got '" + quality + "'");
        }
        ImageSize s = ImageSize.parse("--size", size);
        List<Path> files = new ArrayList<>();
        List<String> pars = new ArrayList<>();
        boolean round = isRound(course);
        if (round) {
            try {
                Round r = RoundLoader.load(course);
                Path folder = course.toAbsolutePath().getParent();
                for (Round.Hole h : r.holes()) {
                    files.add(folder.resolve(h.course()).normalize());
                    pars.add(String.valueOf(h.par()));
                }
            } catch (CourseException e) {
                throw new UserError(e.getMessage());
            }
        } else {
            files.add(course);
        }
        double[] load = loadAverage();
        RenderQuality q = chosen != null ? chosen : RenderQuality.probe();
        int msaa = samples != null ? samples : q.samples();
        List<ObjectNode> results = new ArrayList<>();
        for (Path file : files) results.add(bench(file, CourseArgument.load(file), s, q, msaa));
        ObjectNode out;
        if (round) {
            out = Json.object();
            out.put("round", course.getFileName().toString());
            var holes = out.putArray("holes");
            results.forEach(holes::add);
        } else {
            out = results.get(0);
        }
        if (load != null) {
            var l = out.putArray("loadAverage");
            for (double v : load) l.add(v);
            double[] after = loadAverage();
            if (after != null) {
                var a = out.putArray("loadAverageAfter");
                for (double v : after) a.add(v);
            }
        }
        if (table != null) writeTable(files, pars, results, s, q, msaa, load);
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    /**
     * Whether the file is a round (a JSON object with "holes") rather than a course. Read as every
     * file from others is (a regular UTF-8 file under the course limit; never /dev/zero or a FIFO).
     */
    static boolean isRound(Path file) {
        try {
            String text = minigolf.io.TextFiles.read(file, minigolf.course.Limits.COURSE_FILE_BYTES);
            return text.contains("\"holes\"") && !text.contains("\"terrain\"");
        } catch (java.io.IOException | RuntimeException e) {
            return false; // the course loader reports what is wrong with it
        }
    }

    private ObjectNode bench(Path file, World world, ImageSize s, RenderQuality q, int msaa) {
        ObjectNode out = Json.object();
        try (Offscreen off = new Offscreen(s.width(), s.height(), msaa);
             SceneRenderer renderer = new SceneRenderer(world.course(), world.terrain(), TerrainMesh.ColorMode.GREEN, q)) {
            renderer.setCourseFolder(file.toAbsolutePath().getParent());
            if (waterScale != null) renderer.setWaterTargetScale(waterScale);
            renderer.setWaterReflections(!noReflections);
            renderer.setShadows(!noShadows);
            renderer.setAntiAliasing(msaa == 0 && fxaa);
            OrbitCamera camera = OrbitCamera.behindBall(world.course(), world.terrain(), (float) s.width() / s.height());
            int side = Math.min(s.width(), s.height()) / 4;
            int warmUp = Math.max(5, Math.min(30, frames / 5));
            for (int i = 0; i < warmUp; i++) frame(off, renderer, camera, s, side, i);
            off.finish();
            long cpuStart = FrameClock.processCpuMillis();
            long start = System.nanoTime();
            for (int i = 0; i < frames; i++) frame(off, renderer, camera, s, side, warmUp + i);
            off.finish();
            double ms = (System.nanoTime() - start) / 1e6 / frames;
            long cpuEnd = FrameClock.processCpuMillis();
            if (breakdown) {
                // Timed separately: the glFinish after each pass stalls the pipeline and would inflate msPerFrame.
                renderer.passTimer().setOn(true);
                for (int i = 0; i < frames; i++) frame(off, renderer, camera, s, side, warmUp + frames + i);
                renderer.passTimer().setOn(false);
                ObjectNode passes = out.putObject("passMs");
                renderer.passTimer().millisPerFrame(frames).forEach(passes::put);
                // Triangles each pass sent (GL_PRIMITIVES_GENERATED): llvmpipe's vertex and set-up work is serial.
                ObjectNode sent = out.putObject("passTriangles");
                renderer.passTimer().trianglesPerFrame(frames).forEach(sent::put);
                out.put("terrainVertices", renderer.terrainPass().vertexCount());
                // Of the terrain's indices, those drawn without the shadow tap (-1: every cell keeps it).
                out.put("sunlitTerrainIndices", renderer.terrainPass().sunlitIndexCount());
                out.put("terrainIndices", renderer.terrainPass().indexCount());
                // Level of detail (TerrainLod): surface indices drawn in the last frame, chunks per level (culled ones left out).
                out.put("terrainLodIndices", renderer.terrainPass().lastLodIndexCount());
                var levels = out.putArray("terrainChunksPerLevel");
                for (int n : renderer.terrainPass().lastLevelHistogram()) levels.add(n);
            }
            out.put("frames", frames);
            out.put("msPerFrame", Math.round(ms * 100) / 100.0);
            out.put("fps", Math.round(10000 / ms) / 10.0);
            // CPU time of the whole process (llvmpipe's threads included): steadier than wall time on a shared machine.
            if (cpuStart >= 0 && cpuEnd >= 0) out.put("cpuMsPerFrame", Math.round((cpuEnd - cpuStart) * 10.0 / frames) / 10.0);
            out.put("size", s.width() + "x" + s.height());
            out.put("quality", q.name());
            out.put("samples", msaa);
            out.put("fxaa", renderer.antiAliasing());
            out.put("waterScale", renderer.waterTargetScale());
            out.put("shadows", !noShadows);
            out.put("reflections", !noReflections);
            out.put("course", world.course().name());
            out.put("world", world.course().world());
            out.put("renderer", glGetString(GL_RENDERER));
        }
        return out;
    }

    /** The 1, 5 and 15 minute load averages (Linux), or null. */
    static double[] loadAverage() {
        try {
            String[] f = java.nio.file.Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            return new double[]{Double.parseDouble(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2])};
        } catch (java.io.IOException | RuntimeException e) {
            return null;
        }
    }

    /** The holes' times as a Markdown table, with how they were measured (size, quality, renderer, load, commit). */
    private void writeTable(List<Path> files, List<String> pars, List<ObjectNode> results, ImageSize s, RenderQuality q, int msaa,
                            double[] load) {
        StringBuilder t = new StringBuilder();
        String renderer = results.isEmpty() ? "?" : results.get(0).path("renderer").asText();
        t.append("`minigolf bench-render ").append(course).append(" --quality ").append(q.name()).append(" --size ")
                .append(s.width()).append('x').append(s.height()).append(" --frames ").append(frames).append("`: ")
                .append(renderer).append(", ").append(msaa).append("x MSAA, built from commit ").append(VersionInfo.commit())
                .append(load == null ? "" : String.format(java.util.Locale.ROOT, ", load average %.2f / %.2f / %.2f (1/5/15 min) at the start", load[0], load[1], load[2]))
                .append(".\n\n");
        t.append("| hole | course | par | ms a frame | CPU ms a frame | fps |\n|---|---|---:|---:|---:|---:|\n");
        double worst = 0, worstCpu = 0;
        for (int i = 0; i < results.size(); i++) {
            ObjectNode r = results.get(i);
            double ms = r.path("msPerFrame").asDouble(), cpu = r.path("cpuMsPerFrame").asDouble(Double.NaN);
            worst = Math.max(worst, ms);
            if (!Double.isNaN(cpu)) worstCpu = Math.max(worstCpu, cpu);
            t.append("| ").append(i + 1).append(" | ").append(r.path("course").asText()).append(" | ")
                    .append(i < pars.size() ? pars.get(i) : "").append(" | ").append(r.path("msPerFrame").asText()).append(" | ")
                    .append(Double.isNaN(cpu) ? "" : r.path("cpuMsPerFrame").asText()).append(" | ").append(r.path("fps").asText())
                    .append(" |\n");
        }
        t.append(String.format(java.util.Locale.ROOT, "\nSlowest hole: %.2f ms a frame (wall), %.1f ms of CPU a frame.\n", worst, worstCpu));
        try {
            minigolf.io.AtomicFile.write(table, t.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8));
        } catch (java.io.IOException e) {
            throw new UserError("--table: cannot write " + table + ": " + e.getMessage());
        }
    }

    /** One game-like frame: the camera turns slowly, the water moves, the minimap is drawn; the GPU finishes it. */
    private static void frame(Offscreen off, SceneRenderer renderer, OrbitCamera camera, ImageSize s, int side, int i) {
        camera.rotate(0.002f, 0f);
        off.bind();
        renderer.render(camera, s.width(), s.height(), i / 60f);
        renderer.renderMinimap(s.width() - side - side / 12, side / 12, side, s.width(), s.height());
        off.finish();
    }
}
