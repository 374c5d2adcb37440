package minigolf.editor.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseWriter;
import minigolf.course.HoleRule;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import minigolf.editor.BotCheck;
import minigolf.editor.ChangeSet;
import minigolf.editor.CourseEditor;
import minigolf.editor.EditableCourse;
import minigolf.editor.EditorKey;
import minigolf.editor.ModelCatalog;
import minigolf.editor.ObstacleTools;
import minigolf.editor.Problem;
import minigolf.editor.Recovery;
import minigolf.editor.TerrainPicker;
import minigolf.editor.ToolController;
import minigolf.editor.ZoneTools;
import minigolf.game.BotCatalog;
import minigolf.ui.PlanOverlay;
import minigolf.game.SettingsStore;
import minigolf.game.ShotPlanner;
import minigolf.game.UserSettings;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import minigolf.render.OrbitCamera;
import minigolf.render.Png;
import minigolf.render.RenderQuality;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import minigolf.render.Window;
import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiDouble;
import minigolf.ui.GuiDrawList;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.GuiWindowFlags;
import minigolf.ui.NuklearLayer;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

/**
 * The course editor's window: the game's renderer and orbit camera, Nuklear panels, mouse picking
 * of the terrain and the original keyboard scheme. All editing goes through {@link ToolController}
 * and {@link CourseEditor}; this class only turns input into their calls and draws.
 * Camera (the game's scheme, minigolf.ui.CameraDrag): right drag or Ctrl + left drag turns, Shift + right drag, middle drag
 * or Ctrl + Shift + left drag pans, the wheel zooms; the left button uses the tool.
 */
public final class EditorApp {
    /**
     * How the editor is started.
     *
     * @param scriptedKeys GLFW key presses {key, mods}, one per frame from the first, through the same
     *                     path as the keyboard (tests, the command line)
     * @param recoveryDir  where the autosave goes
     */
    public record Options(Path screenshot, int frames, List<int[]> scriptedKeys, Path recoveryDir, boolean visible) {
    }

    private enum Dialog { NONE, NEW, OPEN, SAVE_AS, RECOVERY, CONFIRM_CLOSE }

    private static final String[] ACTIONS = {"Raise", "Lower", "Smooth", "Flatten", "Paint grass", "Paint sand",
            "Paint friction", "Set height", "Delete cells", "Restore cells", "Place start", "Place hole"};
    private static final String[] KINDS = {"Wall", "Tree", "Box", "Model"};

    private final Options options;
    private final Recovery recovery;
    private CourseEditor editor;
    private ToolController tool;
    private Window window;
    private RenderQuality quality = RenderQuality.HIGH;
    private NuklearLayer uiLayer;
    private SceneRenderer renderer;
    private OrbitCamera camera;
    private boolean heightMap, rebuildScene = true;
    private String message;
    private double messageUntil;
    private List<Problem> problems = List.of();
    private boolean problemsStale = true;
    private double lastValidation = -1;
    private Dialog dialog = Dialog.NONE;
    private BotCheck botCheck;
    private final GuiInt botChoice = new GuiInt(0);
    private Path playFile;
    // Mouse.
    private boolean rotating, panning, stroking, dragging;
    private int dragObject = -1;
    private double dragStartX, dragStartY, lastDabX, lastDabY;
    private double lastX, lastY;
    private boolean cursorSeen;
    // Dialog fields.
    private final GuiString newName = new GuiString("My course", 128), newExpression = new GuiString("", 256);
    private final GuiDouble newWidth = new GuiDouble(10), newDepth = new GuiDouble(6), newSpacing = new GuiDouble(0.05);
    private final GuiString pathField = new GuiString("courses/my-course.json", 512);
    // Panel fields.
    private final GuiDouble startX = new GuiDouble(), startY = new GuiDouble(), holeX = new GuiDouble(), holeY = new GuiDouble();
    private final GuiDouble holeRadius = new GuiDouble(), gravity = new GuiDouble(), kinetic = new GuiDouble(),
            statics = new GuiDouble(), maxSpeed = new GuiDouble();
    private final GuiInt holeRule = new GuiInt(), maxObjects = new GuiInt();
    private final GuiString courseName = new GuiString(128);
    private long fieldsVersion = -1;
    private int selected = -1;
    // The selected object's fields (refreshed when the selection or the course changes) and the selected zone.
    private final GuiDouble objA = new GuiDouble(), objB = new GuiDouble(), objC = new GuiDouble(), objRestitution = new GuiDouble();
    private int selectedFieldsFor = -1;
    private long selectedFieldsVersion = -1;
    private int selectedZone = -1;
    private final GuiDouble zoneKinetic = new GuiDouble(), zoneStatic = new GuiDouble();
    private float time;

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
            installInput();
            float scale = Math.max(1f, window.framebufferHeight() / 900f);
            try (NuklearLayer ui = new NuklearLayer(window.handle(), scale, minigolf.ui.UiFont.EDITOR_SIZE_PIXELS)) {
                uiLayer = ui;
                if (recovery.start()) {
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
                    loop();
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

    private void loop() {
        double start = glfwGetTime();
        int frame = 0;
        while (!window.shouldClose()) {
            double now = glfwGetTime();
            time = (float) (now - start);
            window.pollEvents();
            if (frame < options.scriptedKeys().size()) {
                int[] k = options.scriptedKeys().get(frame);
                onKey(k[0], k[1]);
            }
            int fw = window.framebufferWidth(), fh = window.framebufferHeight();
            if (fw <= 0 || fh <= 0 || window.isIconified()) {
                sleep(50);
                continue;
            }
            applyChanges(now);
            autosave(now);
            drawFrame(fw, fh);
            frame++;
            if (options.frames() > 0 && frame >= Math.max(options.frames(), options.scriptedKeys().size() + 1)) {
                if (options.screenshot() != null) Png.saveBackBuffer(options.screenshot(), fw, fh);
                window.swapBuffers();
                break;
            }
            window.swapBuffers();
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void say(String text) {
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
            if (changes.obstaclesChanged()) renderer.setObstacles(editor.course().obstacles());
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

    // ---- Input ----------------------------------------------------------------------------------

    private void installInput() {
        long h = window.handle();
        glfwSetKeyCallback(h, (win, key, scancode, action, mods) -> {
            if (action == GLFW_RELEASE || (uiLayer != null && uiLayer.wantsKeyboard())) return;
            boolean repeatable = key == GLFW_KEY_W || key == GLFW_KEY_A || key == GLFW_KEY_S || key == GLFW_KEY_D;
            if (action == GLFW_REPEAT && !repeatable) return;
            onKey(key, mods);
        });
        glfwSetWindowCloseCallback(h, win -> {
            if (editor.isDirty()) {
                glfwSetWindowShouldClose(win, false);
                dialog = Dialog.CONFIRM_CLOSE;
            }
        });
        glfwSetMouseButtonCallback(h, (win, button, action, mods) -> {
            boolean down = action == GLFW_PRESS;
            double[] x = new double[1], y = new double[1];
            glfwGetCursorPos(win, x, y);
            lastX = x[0];
            lastY = y[0];
            if (down && uiLayer != null && uiLayer.wantsMouse()) return;
            // The game's camera scheme (CameraDrag): right-drag or Ctrl + left-drag turns, Shift + right,
            // middle or Ctrl + Shift + left moves; a plain left press is the tool.
            minigolf.ui.CameraDrag drag = down ? minigolf.ui.CameraDrag.of(button, mods) : minigolf.ui.CameraDrag.NONE;
            if (down && drag != minigolf.ui.CameraDrag.NONE) {
                rotating = drag == minigolf.ui.CameraDrag.ROTATE;
                panning = drag == minigolf.ui.CameraDrag.PAN;
            } else if (!down && button != GLFW_MOUSE_BUTTON_LEFT) {
                rotating = false;
                panning = false;
            }
            if (button == GLFW_MOUSE_BUTTON_LEFT) {
                if (down && drag == minigolf.ui.CameraDrag.NONE) {
                    toolDown(x[0], y[0]);
                } else if (!down) {
                    if (rotating || panning) {
                        rotating = false;
                        panning = false;
                    }
                    toolUp(x[0], y[0]);
                }
            }
        });
        glfwSetCursorPosCallback(h, (win, x, y) -> {
            if (!cursorSeen) { // the first event only says where the pointer already was (e.g. under Xvfb)
                cursorSeen = true;
                lastX = x;
                lastY = y;
                return;
            }
            float dx = (float) (x - lastX), dy = (float) (y - lastY);
            lastX = x;
            lastY = y;
            if (rotating) {
                camera.rotate(-dx * 0.006f, dy * 0.006f);
            } else if (panning) {
                int[] ww = new int[1], wh = new int[1];
                glfwGetWindowSize(win, ww, wh);
                camera.pan(dx, dy, Math.max(1, wh[0]));
            } else if (uiLayer == null || !uiLayer.wantsMouse()) {
                toolMove(x, y);
            }
        });
        glfwSetScrollCallback(h, (win, xoff, yoff) -> {
            if (uiLayer == null || !uiLayer.wantsMouse()) camera.zoom((float) yoff);
        });
    }

    /** One key press (the GLFW callback and scripted input both end here). */
    public void onKey(int key, int mods) {
        boolean ctrl = (mods & GLFW_MOD_CONTROL) != 0;
        if (ctrl) {
            switch (key) {
                case GLFW_KEY_Z -> say(tool.press(EditorKey.UNDO));
                case GLFW_KEY_Y -> say(tool.press(EditorKey.REDO));
                case GLFW_KEY_S -> save();
                default -> {
                }
            }
            return;
        }
        EditorKey k = switch (key) {
            case GLFW_KEY_W -> EditorKey.UP;
            case GLFW_KEY_A -> EditorKey.LEFT;
            case GLFW_KEY_S -> EditorKey.DOWN;
            case GLFW_KEY_D -> EditorKey.RIGHT;
            case GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT -> EditorKey.TOGGLE_TOOL;
            case GLFW_KEY_M -> EditorKey.WALL;
            case GLFW_KEY_B -> EditorKey.TREE;
            case GLFW_KEY_ENTER, GLFW_KEY_KP_ENTER -> EditorKey.PLACE;
            case GLFW_KEY_P -> EditorKey.DELETE;
            case GLFW_KEY_Q -> EditorKey.ROTATE_LEFT;
            case GLFW_KEY_E -> EditorKey.ROTATE_RIGHT;
            default -> null;
        };
        if (k != null) {
            say(tool.press(k));
            return;
        }
        switch (key) {
            case GLFW_KEY_H -> toggleHeightMap();
            case GLFW_KEY_R -> camera.reset();
            case GLFW_KEY_F11 -> window.toggleFullscreen();
            default -> {
            }
        }
    }

    private void toggleHeightMap() {
        heightMap = !heightMap;
        renderer.terrainPass().setColorMode(heightMap ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN);
    }

    private void toolDown(double cx, double cy) {
        double[] p = pick(cx, cy);
        if (p == null) return;
        tool.moveTo(p[0], p[1]);
        if (tool.isBrushAction()) {
            editor.beginStroke(tool.brush(), p[0], p[1], tool.radius, tool.strength);
            stroking = true;
            lastDabX = p[0];
            lastDabY = p[1];
            return;
        }
        if (tool.mode() == ToolController.Mode.OBJECT) {
            int k = editor.obstacleNear(p[0], p[1], ToolController.PICK_DISTANCE);
            if (k >= 0) { // drag an existing object
                selected = k;
                dragObject = k;
                dragging = true;
                dragStartX = p[0];
                dragStartY = p[1];
                return;
            }
        }
        say(tool.applyAt(p[0], p[1]));
    }

    private void toolMove(double cx, double cy) {
        double[] p = pick(cx, cy);
        if (p == null) return;
        tool.moveTo(p[0], p[1]);
        if (stroking && Math.hypot(p[0] - lastDabX, p[1] - lastDabY) >= 0.25 * tool.radius) {
            editor.dab(p[0], p[1]);
            lastDabX = p[0];
            lastDabY = p[1];
        }
    }

    private void toolUp(double cx, double cy) {
        if (stroking) {
            stroking = false;
            editor.endStroke();
        }
        if (dragging) {
            dragging = false;
            double[] p = pick(cx, cy);
            if (p != null && Math.hypot(p[0] - dragStartX, p[1] - dragStartY) > 1e-3) {
                editor.moveObstacle(dragObject, p[0] - dragStartX, p[1] - dragStartY);
            }
            dragObject = -1;
        }
    }

    /** Cursor (window coordinates) to the terrain point under it, or null. */
    private double[] pick(double cx, double cy) {
        if (camera == null) return null;
        int[] ww = new int[1], wh = new int[1];
        glfwGetWindowSize(window.handle(), ww, wh);
        int fw = window.framebufferWidth(), fh = window.framebufferHeight();
        double x = cx * fw / Math.max(1, ww[0]), y = cy * fh / Math.max(1, wh[0]);
        float nx = (float) (2 * x / fw - 1), ny = (float) (1 - 2 * y / fh);
        Matrix4f inv = camera.viewProjection((float) fw / fh, new Matrix4f()).invert();
        Vector4f near = new Vector4f(nx, ny, -1, 1).mul(inv), far = new Vector4f(nx, ny, 1, 1).mul(inv);
        near.div(near.w);
        far.div(far.w);
        World w = editor.world();
        return TerrainPicker.pick(w.terrain(), w.bounds(), near.x, near.y, near.z, far.x - near.x, far.y - near.y,
                far.z - near.z, 0.5 * editor.course().spacing());
    }

    // ---- Actions --------------------------------------------------------------------------------

    private void save() {
        if (editor.file() == null) {
            openSaveAs();
            return;
        }
        saveTo(editor.file());
    }

    /** "Save as", suggesting the course's file or a new one in the player's courses folder (the game lists it). */
    private void openSaveAs() {
        pathField.set(minigolf.editor.SaveLocation.suggest(options.recoveryDir(), editor.file(), editor.world().course().name()).toString());
        dialog = Dialog.SAVE_AS;
    }

    private boolean saveTo(Path file) {
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

    private void playIt() {
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

    private void askBot() {
        List<String> names = BotCatalog.names();
        if (names.isEmpty()) return;
        ShotPlanner planner = BotCatalog.planner(names.get(Math.min(botChoice.get(), names.size() - 1)));
        if (botCheck != null) botCheck.cancel();
        // Played under the player's game settings: the "realistic" noise and friction hidden from bots.
        UserSettings user = SettingsStore.forUser().loadOrDefaults(null);
        botCheck = BotCheck.start(planner, editor.world(), SimulationSettings.DEFAULT, 12, 1,
                new BotCheck.Conditions(user.noise(), user.hideFrictionFromBots()));
    }

    private void replaceEditor(CourseEditor next) {
        editor.endStroke();
        editor = next;
        tool = new ToolController(next);
        camera = null;
        selected = -1;
        selectedZone = -1;
        fieldsVersion = -1;
        problemsStale = true;
        rebuildScene = true;
    }

    // ---- Drawing --------------------------------------------------------------------------------

    private void drawFrame(int fw, int fh) {
        if (message != null && glfwGetTime() > messageUntil) message = null;
        renderer.render(camera, fw, fh, time);
        int mini = Math.min(fw, fh) / 5;
        renderer.renderMinimap(fw - mini - 12, 40, mini, fw, fh);
        glViewport(0, 0, fw, fh);
        uiLayer.newFrame();
        drawMarkers(fw, fh);
        menuBar();
        toolsPanel(fh);
        coursePanel(fw, fh);
        statusLine(fw, fh);
        dialogs(fw, fh);
        uiLayer.render();
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

    private void menuBar() {
        if (!Gui.beginMainMenuBar()) return;
        if (Gui.beginMenu("File")) {
            if (Gui.menuItem("New...", "")) dialog = Dialog.NEW;
            if (Gui.menuItem("Open...", "")) dialog = Dialog.OPEN;
            if (Gui.menuItem("Save", "Ctrl+S")) save();
            if (Gui.menuItem("Save as...", "")) openSaveAs();
            if (Gui.menuItem("Quit", "")) {
                if (editor.isDirty()) dialog = Dialog.CONFIRM_CLOSE;
                else glfwSetWindowShouldClose(window.handle(), true);
            }
            Gui.endMenu();
        }
        if (Gui.beginMenu("Edit")) {
            String u = editor.undoLabel(), r = editor.redoLabel();
            if (Gui.menuItem("Undo " + (u == null ? "" : u), "Ctrl+Z", false, u != null)) say(tool.press(EditorKey.UNDO));
            if (Gui.menuItem("Redo " + (r == null ? "" : r), "Ctrl+Y", false, r != null)) say(tool.press(EditorKey.REDO));
            Gui.endMenu();
        }
        if (Gui.beginMenu("View")) {
            if (Gui.menuItem("Height map", "H", heightMap, true)) toggleHeightMap();
            if (Gui.menuItem("Reset camera", "R")) camera.reset();
            Gui.endMenu();
        }
        if (Gui.beginMenu("Test")) {
            if (Gui.menuItem("Play it", "")) playIt();
            if (Gui.menuItem("Ask a bot", "")) askBot();
            Gui.endMenu();
        }
        Gui.endMainMenuBar();
    }

    private void toolsPanel(int fh) {
        Gui.setNextWindowPos(8, 32, GuiCond.Always);
        Gui.setNextWindowSize(300, 0, GuiCond.Always);
        Gui.setNextWindowSizeConstraints(300, 0, 300, fh - 32 - 3 * Gui.frameHeight()); // above the status line
        Gui.begin("Tools", GuiWindowFlags.NoMove | GuiWindowFlags.NoResize | GuiWindowFlags.NoCollapse);
        if (Gui.radioButton("Terrain tool", tool.mode() == ToolController.Mode.TERRAIN)) tool.setMode(ToolController.Mode.TERRAIN);
        Gui.sameLine();
        if (Gui.radioButton("Object tool", tool.mode() == ToolController.Mode.OBJECT)) tool.setMode(ToolController.Mode.OBJECT);
        Gui.textDisabled("SHIFT switches, WASD moves,");
        Gui.textDisabled("ENTER applies");
        Gui.separator();
        if (tool.mode() == ToolController.Mode.TERRAIN) {
            ToolController.TerrainAction[] all = ToolController.TerrainAction.values();
            for (int i = 0; i < all.length; i++) {
                if (Gui.radioButton(ACTIONS[i], tool.action() == all[i])) tool.setAction(all[i]);
                if (i % 2 == 0) Gui.sameLine(150);
            }
            Gui.separator();
            float[] rad = {(float) tool.radius}, str = {(float) tool.strength};
            if (Gui.sliderFloat("Radius m", rad, 0.05f, 3f, "%.2f")) tool.radius = rad[0];
            if (Gui.sliderFloat("Strength", str, 0.005f, 1f, "%.3f")) tool.strength = str[0];
            GuiDouble hh = new GuiDouble(tool.typedHeight), k = new GuiDouble(tool.typedKinetic), s = new GuiDouble(tool.typedStatic);
            if (Gui.inputDouble("Height m", hh)) tool.typedHeight = hh.get();
            if (Gui.inputDouble("Typed mu_k", k)) tool.typedKinetic = k.get();
            if (Gui.inputDouble("Typed mu_s", s)) tool.typedStatic = s.get();
            EditableCourse c = editor.course();
            int ni = c.nearestColumn(tool.x()), nj = c.nearestRow(tool.y());
            Gui.text(String.format(Locale.ROOT, "Node (%d, %d): h = %.3f m", ni, nj, c.height(ni, nj)));
            Gui.text(String.format(Locale.ROOT, "mu_k %.3f  mu_s %.3f", c.kineticFriction(ni, nj), c.staticFriction(ni, nj)));
        } else {
            for (int i = 0; i < KINDS.length; i++) {
                if (Gui.radioButton(KINDS[i], tool.kind() == ToolController.ObjectKind.values()[i])) {
                    tool.setKind(ToolController.ObjectKind.values()[i]);
                }
                Gui.sameLine();
            }
            Gui.newLine();
            Gui.textDisabled("M wall, B tree, ENTER places,");
            Gui.textDisabled("P deletes, Q/E turn");
            newObjectSettings();
        }
        Gui.separator();
        List<Obstacle> list = editor.course().obstacles();
        Gui.text("Objects: " + list.size() + " of at most " + editor.maxObstacles());
        for (int i = 0; i < list.size() && i < 200; i++) {
            Vec2 oc = ObstacleTools.center(list.get(i));
            String label = String.format(Locale.ROOT, "%d %s (%.2f, %.2f)##o%d", i, ObstacleTools.describe(list.get(i)), oc.x(), oc.y(), i);
            if (Gui.selectable(label, i == selected)) selected = i;
        }
        if (selected >= 0 && selected < list.size()) {
            if (Gui.button("Turn left")) editor.rotateObstacle(selected, ToolController.ROTATE_STEP_DEG);
            Gui.sameLine();
            if (Gui.button("Turn right")) editor.rotateObstacle(selected, -ToolController.ROTATE_STEP_DEG);
            Gui.sameLine();
            if (Gui.button("Delete")) {
                editor.removeObstacle(selected);
                selected = -1;
            }
            if (selected >= 0) selectedObjectFields(list.get(selected));
        }
        zoneList();
        Gui.end();
    }

    /** Sizes of the objects the tool will place. */
    private void newObjectSettings() {
        switch (tool.kind()) {
            case WALL -> {
                float[] len = {(float) tool.wallLength}, th = {(float) tool.wallThickness}, ht = {(float) tool.wallHeight};
                if (Gui.sliderFloat("Wall length", len, 0.2f, 5f, "%.2f")) tool.wallLength = len[0];
                if (Gui.sliderFloat("Thickness", th, 0f, 0.5f, "%.3f")) tool.wallThickness = th[0];
                if (Gui.sliderFloat("Height", ht, 0.02f, 1f, "%.2f")) tool.wallHeight = Math.max(0.01, ht[0]);
            }
            case TREE -> {
                float[] tr = {(float) tool.treeRadius}, ht = {(float) tool.treeHeight};
                if (Gui.sliderFloat("Tree radius", tr, 0.05f, 0.5f, "%.2f")) tool.treeRadius = tr[0];
                if (Gui.sliderFloat("Tree height", ht, 0.2f, 3f, "%.2f")) tool.treeHeight = ht[0];
            }
            case BOX -> {
                float[] bs = {(float) tool.boxSize}, ht = {(float) tool.boxHeight};
                if (Gui.sliderFloat("Box size", bs, 0.1f, 2f, "%.2f")) tool.boxSize = bs[0];
                if (Gui.sliderFloat("Box height", ht, 0.05f, 2f, "%.2f")) tool.boxHeight = ht[0];
            }
            case MODEL -> {
                List<String> models = ModelCatalog.BUNDLED;
                GuiInt choice = new GuiInt(Math.max(0, models.indexOf(tool.modelFile)));
                if (Gui.combo("Model", choice, models.toArray(new String[0]))) tool.modelFile = models.get(choice.get());
                float[] sc = {(float) tool.modelScale};
                if (Gui.sliderFloat("Scale", sc, 0.1f, 3f, "%.2f")) tool.modelScale = Math.max(0.01, sc[0]);
            }
        }
        float[] re = {(float) tool.restitution};
        if (Gui.sliderFloat("Restitution", re, 0f, 1f, "%.2f")) tool.restitution = re[0];
    }

    /** The selected object's sizes and restitution; a typed value is one undoable edit when the field is left. */
    private void selectedObjectFields(Obstacle o) {
        if (selected != selectedFieldsFor || editor.version() != selectedFieldsVersion) {
            selectedFieldsFor = selected;
            selectedFieldsVersion = editor.version();
            double[] v = sizes(o);
            objA.set(v[0]);
            objB.set(v[1]);
            objC.set(v[2]);
            objRestitution.set(o.restitution());
        }
        try {
            if (o instanceof Obstacle.Wall) {
                Gui.inputDouble("Thickness m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setWallSize(selected, objA.get(), objB.get());
                Gui.inputDouble("Height m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setWallSize(selected, objA.get(), objB.get());
            } else if (o instanceof Obstacle.Tree) {
                Gui.inputDouble("Radius m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setTreeSize(selected, objA.get(), objB.get());
                Gui.inputDouble("Height m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setTreeSize(selected, objA.get(), objB.get());
            } else if (o instanceof Obstacle.Box) {
                Gui.inputDouble("Width m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setBoxSize(selected, objA.get(), objB.get(), objC.get());
                Gui.inputDouble("Depth m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setBoxSize(selected, objA.get(), objB.get(), objC.get());
                Gui.inputDouble("Height m", objC);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setBoxSize(selected, objA.get(), objB.get(), objC.get());
            } else {
                Gui.inputDouble("Scale", objA);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setModelScale(selected, objA.get());
            }
            Gui.inputDouble("Restitution", objRestitution);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setRestitution(selected, objRestitution.get());
        } catch (IllegalArgumentException e) {
            say(e.getMessage());
            selectedFieldsFor = -1; // show the object's values again
        }
    }

    /** The editable sizes of an object, in the order of its fields. */
    private static double[] sizes(Obstacle o) {
        if (o instanceof Obstacle.Wall w) return new double[]{w.thickness(), w.height(), 0};
        if (o instanceof Obstacle.Tree t) return new double[]{t.radius(), t.height(), 0};
        if (o instanceof Obstacle.Box b) {
            return new double[]{b.max().x() - b.min().x(), b.max().y() - b.min().y(), b.max().z() - b.min().z()};
        }
        return new double[]{((Obstacle.Model) o).scale(), 0, 0};
    }

    /** The course's friction zones: listed, deletable, friction editable. */
    private void zoneList() {
        List<Zone> zones = editor.zones();
        if (zones.isEmpty()) return;
        Gui.separator();
        Gui.text("Friction zones: " + zones.size() + " (later ones win)");
        for (int i = 0; i < zones.size(); i++) {
            if (Gui.selectable(i + " " + ZoneTools.describe(zones.get(i)) + "##z" + i, i == selectedZone)) {
                selectedZone = i;
                zoneKinetic.set(zones.get(i).kineticFriction());
                zoneStatic.set(zones.get(i).staticFriction());
            }
        }
        if (selectedZone < 0 || selectedZone >= zones.size()) return;
        Gui.textWrapped(ZoneTools.describe(zones.get(selectedZone))); // the list cuts long lines
        try {
            Gui.inputDouble("Zone mu_k", zoneKinetic);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setZoneFriction(selectedZone, zoneKinetic.get(), zoneStatic.get());
            Gui.inputDouble("Zone mu_s", zoneStatic);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setZoneFriction(selectedZone, zoneKinetic.get(), zoneStatic.get());
            if (Gui.button("Delete zone")) {
                editor.removeZone(selectedZone);
                selectedZone = -1;
            }
        } catch (IllegalArgumentException e) {
            say(e.getMessage());
            zoneKinetic.set(zones.get(selectedZone).kineticFriction());
            zoneStatic.set(zones.get(selectedZone).staticFriction());
        }
    }

    private void syncFields() {
        if (fieldsVersion == editor.version()) return;
        fieldsVersion = editor.version();
        Course c = editor.toCourse();
        startX.set(c.start().x());
        startY.set(c.start().y());
        holeX.set(c.hole().position().x());
        holeY.set(c.hole().position().y());
        holeRadius.set(c.hole().radius());
        holeRule.set(c.hole().rule().ordinal());
        gravity.set(c.physics().gravity());
        kinetic.set(c.physics().kineticFriction());
        statics.set(c.physics().staticFriction());
        maxSpeed.set(c.physics().maxSpeed());
        maxObjects.set(editor.maxObstacles());
        courseName.set(c.name());
    }

    private void coursePanel(int fw, int fh) {
        syncFields();
        Gui.setNextWindowPos(fw - 8, fh - 48, GuiCond.Always, 1f, 1f);
        Gui.setNextWindowSize(330, 0, GuiCond.Always);
        Gui.begin("Course", GuiWindowFlags.NoMove | GuiWindowFlags.NoCollapse);
        try {
            Gui.inputText("Name", courseName);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setName(courseName.get());
            Gui.inputDouble("Start x", startX);
            Gui.inputDouble("Start y", startY);
            if (Gui.button("Set start")) editor.setStart(startX.get(), startY.get());
            Gui.inputDouble("Hole x", holeX);
            Gui.inputDouble("Hole y", holeY);
            if (Gui.button("Set hole")) editor.setHole(holeX.get(), holeY.get());
            Gui.inputDouble("Hole radius", holeRadius);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setHoleRadius(holeRadius.get());
            if (Gui.combo("Hole rule", holeRule, new String[]{"rest", "capture"})) {
                editor.setHoleRule(HoleRule.values()[holeRule.get()]);
            }
            Gui.separator();
            Gui.inputDouble("Gravity", gravity);
            Gui.inputDouble("mu_k", kinetic);
            Gui.inputDouble("mu_s", statics);
            Gui.inputDouble("Max speed", maxSpeed);
            if (Gui.button("Apply physics")) {
                PhysicsSettings p = editor.toCourse().physics();
                editor.setPhysics(new PhysicsSettings(gravity.get(), kinetic.get(), statics.get(), maxSpeed.get(), p.model(),
                        p.ballRadius(), p.ballMass(), p.dragCoefficient(), p.airDensity(), p.groundRestitution()));
            }
            if (Gui.inputInt("Max objects", maxObjects)) editor.setMaxObstacles(Math.max(0, maxObjects.get()));
        } catch (IllegalArgumentException e) {
            say(e.getMessage());
            fieldsVersion = -1;
        }
        Gui.separator();
        if (problems.isEmpty()) {
            Gui.textColored(0.5f, 1f, 0.5f, 1f, "No problems: ready to save");
        } else {
            for (Problem p : problems) Gui.textColored(1f, 0.4f, 0.4f, 1f, p.message());
        }
        Gui.separator();
        List<String> names = BotCatalog.names();
        Gui.setNextItemWidth(120);
        Gui.combo("##bot", botChoice, names.toArray(new String[0]));
        Gui.sameLine();
        if (Gui.button("Ask a bot")) askBot();
        Gui.sameLine();
        if (Gui.button("Play it")) playIt();
        if (botCheck != null) {
            if (!botCheck.isDone()) {
                Gui.text(botCheck.message());
                Gui.progressBar((float) botCheck.progress(), 200, 0);
                Gui.sameLine();
                if (Gui.button("Cancel##bot")) botCheck.cancel();
            } else if (botCheck.result() != null) Gui.text(botCheck.result().describe());
            else Gui.text(botCheck.failure());
        }
        Gui.end();
    }

    private void statusLine(int fw, int fh) {
        Gui.setNextWindowPos(8, fh - 8, GuiCond.Always, 0f, 1f);
        Gui.begin("##status", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        String state = editor.isDirty() ? "unsaved changes" : "saved";
        String tip = String.format(Locale.ROOT, "%s | tool (%.2f, %.2f) | %s%s", state, tool.x(), tool.y(),
                tool.mode() == ToolController.Mode.TERRAIN ? "terrain: " + tool.action().label()
                        : "object: " + tool.kind().name().toLowerCase(Locale.ROOT),
                message != null ? " | " + message : "");
        Gui.text(tip);
        Gui.end();
    }

    private void dialogs(int fw, int fh) {
        if (dialog == Dialog.NONE) return;
        Gui.setNextWindowPos(fw * 0.5f, fh * 0.5f, GuiCond.Always, 0.5f, 0.5f);
        Gui.begin("##dialog", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
        switch (dialog) {
            case NEW -> {
                Gui.text("New course");
                Gui.inputText("Name", newName);
                Gui.inputDouble("Width m", newWidth);
                Gui.inputDouble("Depth m", newDepth);
                Gui.inputDouble("Grid spacing m", newSpacing);
                Gui.inputText("Height h(x, y)", newExpression);
                Gui.textDisabled("empty: flat; e.g. 0.2 + 0.1*sin(x)*cos(y)");
                if (Gui.button("Create")) {
                    try {
                        replaceEditor(CourseEditor.create(newName.get(), newWidth.get(), newDepth.get(), newSpacing.get(),
                                newExpression.get()));
                        dialog = Dialog.NONE;
                    } catch (IllegalArgumentException e) {
                        say(e.getMessage());
                    }
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) dialog = Dialog.NONE;
            }
            case OPEN, SAVE_AS -> {
                Gui.text(dialog == Dialog.OPEN ? "Open course file" : "Save course as");
                Gui.setNextItemWidth(420);
                Gui.inputText("##path", pathField);
                if (Gui.button(dialog == Dialog.OPEN ? "Open" : "Save")) {
                    Path p = Path.of(pathField.get().trim());
                    if (dialog == Dialog.OPEN) {
                        try {
                            replaceEditor(CourseEditor.open(p));
                            dialog = Dialog.NONE;
                        } catch (CourseException e) {
                            say(e.getMessage());
                        }
                    } else if (saveTo(p)) {
                        dialog = Dialog.NONE;
                    }
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) dialog = Dialog.NONE;
            }
            case RECOVERY -> {
                Gui.text("The editor did not close cleanly last time.");
                Gui.text("Recover the unsaved course from " + recovery.file() + "?");
                if (Gui.button("Recover")) {
                    try {
                        replaceEditor(CourseEditor.recovered(recovery.load()));
                        recovery.release();
                        say("recovered: save it to keep it");
                    } catch (CourseException e) {
                        say(e.getMessage());
                    }
                    dialog = Dialog.NONE;
                }
                Gui.sameLine();
                if (Gui.button("Discard")) {
                    recovery.clear();
                    dialog = Dialog.NONE;
                }
            }
            case CONFIRM_CLOSE -> {
                Gui.text("The course has unsaved changes.");
                if (Gui.button("Save and close")) {
                    if (editor.file() == null) openSaveAs();
                    else if (saveTo(editor.file())) glfwSetWindowShouldClose(window.handle(), true);
                }
                Gui.sameLine();
                if (Gui.button("Close without saving")) {
                    dialog = Dialog.NONE;
                    editor.endStroke();
                    glfwSetWindowShouldClose(window.handle(), true);
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) dialog = Dialog.NONE;
            }
            default -> {
            }
        }
        Gui.end();
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
