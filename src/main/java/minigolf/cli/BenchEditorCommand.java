package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Arrays;
import java.util.concurrent.Callable;
import minigolf.editor.Brush;
import minigolf.editor.ChangeSet;
import minigolf.editor.CourseEditor;
import minigolf.editor.EditableCourse;
import minigolf.physics.World;
import minigolf.render.Offscreen;
import minigolf.render.TerrainMesh;
import minigolf.render.TerrainPass;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import static org.lwjgl.opengl.GL11.glFinish;
import static org.lwjgl.opengl.GL11.glGetString;
import static org.lwjgl.opengl.GL11.GL_RENDERER;

@Command(name = "bench-editor", description = {"Times brush dabs on a 256x256-cell grid as the editor does them:",
        "the edit, the physics update (the world rebuilt for the changed grid), the mesh rows re-sampled and,",
        "with --gl, uploaded with glBufferSubData. Prints milliseconds per dab (median and 95th percentile)."})
final class BenchEditorCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--dabs", paramLabel = "N", description = "Brush dabs to time (default: ${DEFAULT-VALUE}).")
    int dabs = 300;

    @Option(names = "--radius", paramLabel = "M", description = "Brush radius in metres (default: ${DEFAULT-VALUE}).")
    double radius = 0.5;

    @Option(names = "--cells", paramLabel = "N", description = "Grid cells a side (default: ${DEFAULT-VALUE}).")
    int cells = 256;

    @Option(names = "--gl", description = "Also upload each dab's mesh rows to a GL buffer (needs OpenGL; default: off).")
    boolean gl;

    @Override
    public Integer call() {
        if (dabs < 10) throw new UserError("--dabs: must be at least 10, got " + dabs);
        if (!(radius > 0)) throw new UserError("--radius: must be > 0");
        if (cells < 8 || cells > 512) throw new UserError("--cells: must be 8 to 512, got " + cells);
        double spacing = 0.04, side = cells * spacing;
        CourseEditor editor = CourseEditor.create("bench", side, side, spacing, "0.3 + 0.2*sin(x)*cos(0.7*y)");
        ObjectNode out = Json.object();
        double[] edit = new double[dabs], physics = new double[dabs], mesh = new double[dabs], upload = new double[dabs];
        if (gl) {
            try (Offscreen off = new Offscreen(64, 64, 0)) {
                World w0 = editor.world();
                try (TerrainPass pass = new TerrainPass(w0.course(), w0.terrain(), TerrainMesh.ColorMode.GREEN)) {
                    run(editor, edit, physics, mesh, upload, pass);
                    long t = System.nanoTime();
                    World w = editor.world();
                    pass.rebuild(w.course(), w.terrain());
                    glFinish();
                    out.put("fullMeshRebuildMs", round((System.nanoTime() - t) / 1e6));
                    out.put("renderer", glGetString(GL_RENDERER));
                }
            }
        } else {
            run(editor, edit, physics, mesh, null, null);
        }
        double[] total = new double[dabs];
        for (int i = 0; i < dabs; i++) total[i] = edit[i] + physics[i] + mesh[i] + upload[i];
        out.put("grid", cells + "x" + cells + " cells, spacing " + spacing + " m");
        out.put("brushRadius", radius);
        out.put("nodesPerDab", (int) Math.round(Math.PI * radius * radius / (spacing * spacing)));
        out.put("dabs", dabs);
        put(out, "editMs", edit);
        put(out, "physicsUpdateMs", physics);
        put(out, "meshRowsMs", mesh);
        if (gl) put(out, "uploadMs", upload);
        put(out, "totalMs", total);
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    /** Dabs along a circle over the course, as a drag would make them; a warm-up first. */
    private void run(CourseEditor editor, double[] edit, double[] physics, double[] mesh, double[] upload, TerrainPass pass) {
        EditableCourse c = editor.course();
        double cx = c.nodeX(c.columns() / 2), cy = c.nodeY(c.rows() / 2), r = 0.3 * (c.columns() - 1) * c.spacing();
        int warm = 30;
        editor.beginStroke(Brush.RAISE, cx + r, cy, radius, 0.002);
        for (int k = -warm; k < edit.length; k++) {
            double a = 2 * Math.PI * (k + warm) / 97.0, x = cx + r * Math.cos(a), y = cy + r * Math.sin(a);
            long t0 = System.nanoTime();
            editor.dab(x, y);
            ChangeSet ch = editor.takeChanges();
            long t1 = System.nanoTime();
            World w = editor.world();
            long t2 = System.nanoTime();
            int[] n = ch.nodeRange();
            double pad = 2 * c.spacing();
            double x0 = c.nodeX(Math.max(0, n[0])) - pad, y0 = c.nodeY(Math.max(0, n[1])) - pad;
            double x1 = c.nodeX(Math.max(0, n[2])) + pad, y1 = c.nodeY(Math.max(0, n[3])) + pad;
            TerrainMesh.Patch p = TerrainMesh.surfacePatch(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN,
                    pass != null ? pass.minHeight() : 0, pass != null ? pass.maxHeight() : 1, x0, y0, x1, y1);
            long t3 = System.nanoTime();
            if (pass != null) {
                pass.applyPatch(p);
                glFinish();
            }
            long t4 = System.nanoTime();
            if (k < 0) continue;
            edit[k] = (t1 - t0) / 1e6;
            physics[k] = (t2 - t1) / 1e6;
            mesh[k] = (t3 - t2) / 1e6;
            upload[k] = (t4 - t3) / 1e6;
        }
        editor.endStroke();
    }

    private static void put(ObjectNode out, String name, double[] ms) {
        double[] s = ms.clone();
        Arrays.sort(s);
        ObjectNode o = out.putObject(name);
        o.put("median", round(s[s.length / 2]));
        o.put("p95", round(s[(int) Math.floor(0.95 * (s.length - 1))]));
        o.put("max", round(s[s.length - 1]));
    }

    private static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
