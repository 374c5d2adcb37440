package minigolf.editor.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseWriter;
import minigolf.course.Vec2;
import minigolf.editor.BotCheck;
import minigolf.editor.ChangeSet;
import minigolf.editor.CourseEditor;
import minigolf.editor.EditableCourse;
import minigolf.editor.ObstacleTools;
import minigolf.editor.Problem;
import minigolf.editor.Recovery;
import minigolf.editor.ToolController;
import minigolf.game.BotCatalog;
import minigolf.ui.PlanOverlay;
import minigolf.game.SettingsStore;
import minigolf.game.ShotPlanner;
import minigolf.game.UserSettings;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import minigolf.render.OrbitCamera;
import minigolf.render.RenderQuality;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import minigolf.render.Window;
import minigolf.render.WindowApp;
import minigolf.render.WindowLoop;
import minigolf.ui.Gui;
import minigolf.ui.GuiDrawList;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.NuklearLayer;
import org.joml.Vector3f;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

/**
 * The course editor's window: the game's renderer and orbit camera, Nuklear panels, mouse picking
 * of the terrain and the original keyboard scheme. All editing goes through {@link ToolController}
 * and {@link CourseEditor}; this class only turns input into their calls and draws.
 * Camera (the game's scheme, minigolf.ui.CameraDrag): right drag or Ctrl + left drag turns, Shift + right drag, middle drag
 * or Ctrl + Shift + left drag pans, the wheel zooms; the left button uses the tool.
 */
public final class EditorApp implements WindowApp {
    /**
     * How the editor is started.
     *
     * @param scriptedKeys GLFW key presses {key, mods}, one per frame from the first, through the same
     *                     path as the keyboard (tests, the command line)
     * @param recoveryDir  where the autosave goes
     */
    public record Options(Path screenshot, int frames, List<int[]> scriptedKeys, Path recoveryDir, boolean visible) {
    }

    enum Dialog { NONE, NEW, OPEN, SAVE_AS, RECOVERY, CONFIRM_CLOSE }


    private final Options options;
    /** The menu bar, the Tools and Course panels, the status line and the dialogs. */
    private final EditorPanels panels = new EditorPanels(this);
    final Recovery recovery;
    CourseEditor editor;
    ToolController tool;
    Window window;
    private RenderQuality quality = RenderQuality.HIGH;
    NuklearLayer uiLayer;
    private SceneRenderer renderer;
    OrbitCamera camera;
    boolean heightMap, rebuildScene = true;
    String message;
    private double messageUntil;
    List<Problem> problems = List.of();
    private boolean problemsStale = true;
    private double lastValidation = -1;
    Dialog dialog = Dialog.NONE;
    /** Why the recovery dialog offers a course: a session that did not close, or a save that did not finish. */
    String recoveryReason = "The editor did not close cleanly last time.";
    BotCheck botCheck;
    final GuiInt botChoice = new GuiInt(0);
    private Path playFile;
    /** Keys and mouse: the tool, dragging objects, the camera. */
    private final EditorInput input = new EditorInput(this);
    final GuiString pathField = new GuiString("courses/my-course.json", 512);
    long fieldsVersion = -1;
    int selected = -1;
    int selectedZone = -1;
    /** The selected push zone, magnet or teleport: an index into ElementPanels' combined list, or -1. */
    int selectedElement = -1;
    float time;
    /** The loop's clock at this pass (autosave and validation pace themselves by it). */
    private double now;
    private int framesDrawn, keysPlayed;

    public EditorApp(CourseEditor editor, Options options) {
        this.editor = editor;
        this.tool = new ToolController(editor);
        this.options = options;
        this.recovery = new Recovery(options.recoveryDir());
    }

    public CourseEditor editor() {
        return editor;
    }

    /** Runs until the window closes or the frames are done; returns the editor at the end. */
    public CourseEditor run() {
        quality = RenderQuality.probe(); // llvmpipe: no MSAA, smaller water targets (docs/rendering.md)
        Window.Options wo = options.visible() ? new Window.Options(true, true, quality.samples(), true, 3, 3)
                : new Window.Options(true, false, 0, true, 3, 3);
        try (Window w = new Window("Minigolf editor", 1400, 860, wo)) {
            window = w;
            window.setVsync(options.frames() <= 0);
            input.install();
            float scale = Math.max(1f, window.framebufferHeight() / 900f);
            try (NuklearLayer ui = new NuklearLayer(window.handle(), scale, minigolf.ui.UiFont.EDITOR_SIZE_PIXELS)) {
                uiLayer = ui;
                boolean waiting = recovery.start();
                if (!waiting && recovery.adoptUnfinishedSave(editor.file())) {
                    waiting = true;
                    recoveryReason = "A save of " + editor.file().getFileName() + " did not finish last time.";
                }
                if (waiting) {
                    if (options.frames() <= 0) {
                        dialog = Dialog.RECOVERY;
                    } else {
                        // A scripted run cannot ask: it keeps the file for the next interactive start and says so.
                        System.err.println("minigolf: a recovery file from an editor session that did not close is"
                                + " kept: " + recovery.file() + " (open the editor without --frames to recover it);"
                                + " this run does not autosave");
                    }
                }
                try {
                    buildScene();
                    new WindowLoop(window, this).screenshot(options.screenshot()).run();
                } finally {
                    if (botCheck != null) botCheck.cancel();
                    if (renderer != null) renderer.close();
                }
            }
        }
        // A normal exit: the recovery file is no longer needed (a crash leaves it for the next start).
        recovery.closeCleanly();
        if (playFile != null) playFile.toFile().delete();
        return editor;
    }

    // ---- The window loop (minigolf.render.WindowLoop, shared with the game) ---------------------

    @Override
    public void update(double elapsed, double now) {
        this.now = now;
        // One scripted key a drawn frame, from the first, through the keyboard's path.
        if (keysPlayed < options.scriptedKeys().size() && keysPlayed <= framesDrawn) {
            int[] k = options.scriptedKeys().get(keysPlayed++);
            input.onKey(k[0], k[1]);
        }
    }

    @Override
    public void render(int fw, int fh, float time) {
        this.time = time;
        applyChanges(now);
        autosave(now);
        drawFrame(fw, fh);
        framesDrawn++;
    }

    @Override
    public boolean finished(int frames) {
        return options.frames() > 0 && frames >= Math.max(options.frames(), options.scriptedKeys().size() + 1);
    }

    void say(String text) {
        if (text == null) return;
        message = text;
        messageUntil = glfwGetTime() + 5;
    }

    // ---- Scene updates -----------------------------------------------------------------------

    /** Brings the drawn scene up to date with the edits of this frame. */
    private void applyChanges(double now) {
        ChangeSet changes = editor.takeChanges();
        if (!changes.isEmpty()) problemsStale = true;
        if (rebuildScene || changes.structureChanged() || (changes.hasNodes() && !editor.isStroking())) {
            buildScene();
        } else {
            if (changes.hasNodes()) {
                int[] r = changes.nodeRange();
                EditableCourse c = editor.course();
                // Bicubic interpolation reaches two nodes beyond a changed node.
                double pad = 2 * c.spacing();
                World w = editor.world();
                renderer.terrainPass().updateRegion(w.course(), w.terrain(), c.nodeX(r[0]) - pad, c.nodeY(r[1]) - pad,
                        c.nodeX(r[2]) + pad, c.nodeY(r[3]) + pad);
                // Ground lowered below zero is water at once, ground raised out of it dry at once (not only
                // when the stroke ends and the scene is rebuilt).
                if (renderer.waterPass().hasWater() || minigolf.editor.CourseWater.anyBelowZero(c, r)) renderer.updateWater(w.course(), w.terrain());
                // The sun's shadow map and the minimap are redrawn once, when the stroke ends and the
                // scene is rebuilt: redrawing them for every dab would cost more than the dab itself.
            }
            if (changes.obstaclesChanged()) {
                // The course's bricks (kept, not editable) stay drawn, every one standing.
                renderer.setObstacles(editor.world().course().obstaclesWithBricks(i -> true));
                renderer.setElements(editor.world().course());
            }
        }
        // Validation (A* included) after the course settles, at most twice a second.
        if (problemsStale && !editor.isStroking() && now - lastValidation > 0.5) {
            problems = editor.validate();
            problemsStale = false;
            lastValidation = now;
        }
    }

    private void buildScene() {
        rebuildScene = false;
        World w = editor.world();
        if (renderer != null) renderer.close();
        renderer = null;
        renderer = new SceneRenderer(w.course(), w.terrain(),
                heightMap ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN, quality);
        if (editor.file() != null) renderer.setCourseFolder(editor.file().toAbsolutePath().getParent());
        if (camera == null) {
            int fw = Math.max(1, window.framebufferWidth()), fh = Math.max(1, window.framebufferHeight());
            camera = OrbitCamera.behindBall(w.course(), w.terrain(), (float) fw / fh);
        }
        String file = editor.file() == null ? "unsaved" : editor.file().getFileName().toString();
        window.setTitle("Minigolf editor - " + w.course().name() + " (" + file + ")");
    }

    private void autosave(double now) {
        try {
            if (recovery.autosave(editor, now)) say("autosaved to " + recovery.file());
        } catch (IOException | RuntimeException e) {
            say("autosave failed: " + e.getMessage());
        }
    }

    /** One key press (the GLFW callback and scripted input both end here). */
    public void onKey(int key, int mods) {
        input.onKey(key, mods);
    }

    void toggleHeightMap() {
        heightMap = !heightMap;
        renderer.terrainPass().setColorMode(heightMap ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN);
    }

    // ---- Actions --------------------------------------------------------------------------------

    void save() {
        if (editor.file() == null) {
            openSaveAs();
            return;
        }
        saveTo(editor.file());
    }

    /** "Save as", suggesting the course's file or a new one in the player's courses folder (the game lists it). */
    void openSaveAs() {
        pathField.set(minigolf.editor.SaveLocation.suggest(options.recoveryDir(), editor.file(), editor.world().course().name()).toString());
        dialog = Dialog.SAVE_AS;
    }

    boolean saveTo(Path file) {
        try {
            if (file.toAbsolutePath().getParent() != null) java.nio.file.Files.createDirectories(file.toAbsolutePath().getParent());
            editor.saveAs(file);
            say("saved " + file);
            rebuildScene = true; // the title shows the file
            return true;
        } catch (IOException e) {
            say("cannot save: " + e.getMessage());
            return false;
        } catch (CourseException e) {
            say(e.getMessage());
            problems = editor.validate();
            return false;
        }
    }

    void playIt() {
        try {
            Course c = editor.toCourse();
            Path folder = editor.file() != null ? editor.file().toAbsolutePath().getParent() : options.recoveryDir();
            java.nio.file.Files.createDirectories(folder);
            playFile = folder.resolve(".editor-play.json");
            CourseWriter.save(c, playFile);
            ProcessLauncher.start(playArguments(playFile).toArray(new String[0]));
            say("the game opens in its own window");
        } catch (IOException | CourseException e) {
            say("cannot play: " + e.getMessage());
        }
    }

    /** The command line of "Play it": a game at once with one player, on the tee (not the main menu). */
    static List<String> playArguments(Path course) {
        return List.of("play", course.toString(), "--players", "Player");
    }

    void askBot() {
        List<String> names = BotCatalog.names();
        if (names.isEmpty()) return;
        ShotPlanner planner = BotCatalog.planner(names.get(Math.min(botChoice.get(), names.size() - 1)));
        if (botCheck != null) botCheck.cancel();
        // Played under the player's game settings: the "realistic" noise and friction hidden from bots.
        UserSettings user = SettingsStore.forUser().loadOrDefaults(null);
        botCheck = BotCheck.start(planner, editor.world(), SimulationSettings.DEFAULT, 12, 1,
                new BotCheck.Conditions(user.noise(), user.hideFrictionFromBots()));
    }

    /** Opens a course file in the editor; returns whether a save of it that did not finish is now offered. */
    boolean openFile(Path file) throws CourseException {
        replaceEditor(CourseEditor.open(file));
        if (!recovery.adoptUnfinishedSave(file)) return false;
        recoveryReason = "A save of " + file.getFileName() + " did not finish last time.";
        return true;
    }

    void replaceEditor(CourseEditor next) {
        editor.endStroke();
        editor = next;
        tool = new ToolController(next);
        camera = null;
        selected = -1;
        selectedZone = -1;
        selectedElement = -1;
        fieldsVersion = -1;
        problemsStale = true;
        rebuildScene = true;
    }

    // ---- Drawing --------------------------------------------------------------------------------

    private void drawFrame(int fw, int fh) {
        if (message != null && glfwGetTime() > messageUntil) message = null;
        // The moving obstacles run on the window's clock: the designer sees them move as they will in play.
        renderer.setClock(time);
        renderer.render(camera, fw, fh, time);
        int mini = minimapSize(fw, fh);
        renderer.renderMinimap(fw - MINIMAP_MARGIN - mini, MINIMAP_TOP, mini, fw, fh);
        glViewport(0, 0, fw, fh);
        uiLayer.newFrame();
        drawMarkers(fw, fh);
        panels.menuBar();
        panels.toolsPanel(fh);
        panels.coursePanel(fw, fh);
        panels.statusLine(fw, fh);
        panels.dialogs(fw, fh);
        uiLayer.render();
    }

    /** The minimap's top and right margin, framebuffer pixels (below the menu bar). */
    static final int MINIMAP_TOP = 40, MINIMAP_MARGIN = 12;

    /**
     * The minimap's side: a fifth of the window, but never reaching down into the Course panel,
     * which grows up from the bottom right (a 1366 x 768 laptop leaves it about 140 px).
     */
    int minimapSize(int fw, int fh) {
        float toPixels = uiLayer == null ? 1 : fw / Math.max(1f, uiLayer.displayWidth());
        return minimapSize(fw, fh, panels.courseTop() * toPixels);
    }

    /** As above, the Course panel's top at {@code courseTop} framebuffer pixels. */
    static int minimapSize(int fw, int fh, float courseTop) {
        int wanted = Math.min(fw, fh) / 5;
        float room = courseTop - MINIMAP_TOP - 8;
        return (int) Math.max(Math.min(wanted, room), Math.min(wanted, 64));
    }

    /** Screen position of a point on the course, in interface (window, top-left) pixels; null behind the camera. */
    private float[] screen(double x, double y, double z) {
        float[] p = camera.project(new Vector3f((float) x, (float) y, (float) z), window.framebufferWidth(), window.framebufferHeight());
        return uiLayer == null ? p : uiLayer.toInterface(p, window.framebufferWidth());
    }

    private void drawMarkers(int fw, int fh) {
        GuiDrawList dl = Gui.getBackgroundDrawList();
        World w = editor.world();
        if (botCheck != null && !botCheck.isDone()) {
            PlanOverlay.draw(dl, botCheck.plan(), p -> screen(p[0], p[1], w.terrain().height(p[0], p[1]) + 0.03));
        }
        // The tool: a ring on the terrain (the brush radius) or a cross for the object tool.
        double tx = tool.x(), ty = tool.y();
        int toolColour = tool.mode() == ToolController.Mode.TERRAIN ? 0xFF40E0FF : 0xFFFF9040; // ABGR
        double r = tool.mode() == ToolController.Mode.TERRAIN ? tool.radius : ToolController.PICK_DISTANCE;
        float[] prev = null;
        for (int k = 0; k <= 48; k++) {
            double a = 2 * Math.PI * k / 48, x = tx + r * Math.cos(a), y = ty + r * Math.sin(a);
            float[] s = screen(x, y, w.terrain().height(x, y) + 0.01);
            if (s != null && prev != null) dl.addLine(prev[0], prev[1], s[0], s[1], toolColour, 2f);
            prev = s;
        }
        float[] c = screen(tx, ty, w.terrain().height(tx, ty));
        if (c != null) {
            dl.addLine(c[0] - 8, c[1], c[0] + 8, c[1], toolColour, 2f);
            dl.addLine(c[0], c[1] - 8, c[0], c[1] + 8, toolColour, 2f);
        }
        // Start: a labelled ring (the ball is drawn by the renderer).
        Vec2 st = w.course().start();
        float[] s = screen(st.x(), st.y(), w.terrain().height(st.x(), st.y()));
        if (s != null) {
            dl.addCircle(s[0], s[1], 10, 0xFFFFFFFF, 20, 2f);
            dl.addText(s[0] + 12, s[1] - 8, 0xFFFFFFFF, "start");
        }
        if (selected >= 0 && selected < editor.course().obstacles().size()) {
            Vec2 oc = ObstacleTools.center(editor.course().obstacles().get(selected));
            float[] o = screen(oc.x(), oc.y(), w.terrain().height(oc.x(), oc.y()) + 0.05);
            if (o != null) dl.addCircle(o[0], o[1], 14, 0xFF00FFFF, 24, 3f);
        }
        // Validation problems where they are.
        for (Problem p : problems) {
            float[] q = screen(p.x(), p.y(), Math.max(0, w.terrain().height(p.x(), p.y())));
            if (q == null) continue;
            dl.addCircle(q[0], q[1], 18, 0xFF2020FF, 24, 4f);
            dl.addLine(q[0] - 12, q[1] - 12, q[0] + 12, q[1] + 12, 0xFF2020FF, 4f);
            dl.addLine(q[0] - 12, q[1] + 12, q[0] + 12, q[1] - 12, 0xFF2020FF, 4f);
            dl.addText(q[0] + 20, q[1] + 14, 0xFF4040FF, p.message());
        }
    }

    /**
     * A key for scripted input: a letter (W, A, S, D, M, B, P, Q, E, H), ENTER, SHIFT, or CTRL+Z,
     * CTRL+Y, CTRL+S. Returns {glfwKey, mods}.
     *
     * @throws IllegalArgumentException for a name it does not know
     */
    public static int[] parseKey(String name) {
        String n = name.trim().toUpperCase(Locale.ROOT);
        int mods = 0;
        if (n.startsWith("CTRL+")) {
            mods = GLFW_MOD_CONTROL;
            n = n.substring(5);
        }
        int key = switch (n) {
            case "ENTER" -> GLFW_KEY_ENTER;
            case "SHIFT" -> GLFW_KEY_LEFT_SHIFT;
            default -> n.length() == 1 && n.charAt(0) >= 'A' && n.charAt(0) <= 'Z' ? GLFW_KEY_A + (n.charAt(0) - 'A') : -1;
        };
        if (key < 0) throw new IllegalArgumentException("unknown key '" + name + "' (letters, ENTER, SHIFT, CTRL+letter)");
        return new int[]{key, mods};
    }

    /** The problems shown on the course now (for tests). */
    public List<Problem> problems() {
        return new ArrayList<>(problems);
    }
}
