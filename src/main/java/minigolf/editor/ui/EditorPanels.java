package minigolf.editor.ui;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.HoleRule;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsSettings;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import minigolf.editor.CourseEditor;
import minigolf.editor.EditableCourse;
import minigolf.editor.EditorKey;
import minigolf.editor.ModelCatalog;
import minigolf.editor.ObstacleTools;
import minigolf.editor.Problem;
import minigolf.editor.ToolController;
import minigolf.editor.ZoneTools;
import minigolf.game.BotCatalog;
import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiDouble;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.GuiWindowFlags;
import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

/**
 * The editor's panels, drawn each frame on the interface layer: the menu bar, the Tools panel
 * (actions, brush, new objects, the selected object's fields, zones), the Course panel (start, hole,
 * physics, problems, "Ask a bot", "Play it"), the status line and the dialogs. The window, input and
 * scene stay in {@link EditorApp}.
 */
final class EditorPanels {
    private static final String[] ACTIONS = {"Raise", "Lower", "Smooth", "Flatten", "Paint grass", "Paint sand",
            "Paint friction", "Set height", "Delete cells", "Restore cells", "Place start", "Place hole"};
    private static final ToolController.ObjectKind[] KINDS = ToolController.ObjectKind.values();
    /** How many characters (label plus 4 for the button) of object kinds fit one row of the Tools panel. */
    private static final int KIND_ROW_CHARS = 38;

    private final EditorApp app;
    // Dialog and panel fields.
    private final GuiString newName = new GuiString("My course", 128), newExpression = new GuiString("", 256);
    private final GuiDouble newWidth = new GuiDouble(10), newDepth = new GuiDouble(6), newSpacing = new GuiDouble(0.05);
    private final GuiDouble startX = new GuiDouble(), startY = new GuiDouble(), holeX = new GuiDouble(), holeY = new GuiDouble();
    private final GuiInt holeRule = new GuiInt(), maxObjects = new GuiInt();
    private final GuiString courseName = new GuiString(128);
    private final GuiDouble objA = new GuiDouble(), objB = new GuiDouble(), objC = new GuiDouble(), objRestitution = new GuiDouble();
    /** Where the Course panel's top was last drawn (interface units): the minimap stays above it. */
    private float courseTop = Float.MAX_VALUE;
    private int selectedFieldsFor = -1;
    /** The push zones', magnets' and teleports' lists and the moving obstacles' fields. */
    private final ElementPanels elements = new ElementPanels();
    private long selectedFieldsVersion = -1;
    private final GuiDouble zoneKinetic = new GuiDouble(), zoneStatic = new GuiDouble();
    private final GuiDouble holeRadius = new GuiDouble(), gravity = new GuiDouble(), kinetic = new GuiDouble(),
            statics = new GuiDouble(), maxSpeed = new GuiDouble();

    EditorPanels(EditorApp app) {
        this.app = app;
    }

    void menuBar() {
        if (!Gui.beginMainMenuBar()) return;
        if (Gui.beginMenu("File")) {
            if (Gui.menuItem("New...", "")) app.dialog = EditorApp.Dialog.NEW;
            if (Gui.menuItem("Open...", "")) app.dialog = EditorApp.Dialog.OPEN;
            if (Gui.menuItem("Save", "Ctrl+S")) app.save();
            if (Gui.menuItem("Save as...", "")) app.openSaveAs();
            if (Gui.menuItem("Quit", "")) {
                if (app.editor.isDirty()) app.dialog = EditorApp.Dialog.CONFIRM_CLOSE;
                else glfwSetWindowShouldClose(app.window.handle(), true);
            }
            Gui.endMenu();
        }
        if (Gui.beginMenu("Edit")) {
            String u = app.editor.undoLabel(), r = app.editor.redoLabel();
            if (Gui.menuItem("Undo " + (u == null ? "" : u), "Ctrl+Z", false, u != null)) app.say(app.tool.press(EditorKey.UNDO));
            if (Gui.menuItem("Redo " + (r == null ? "" : r), "Ctrl+Y", false, r != null)) app.say(app.tool.press(EditorKey.REDO));
            Gui.endMenu();
        }
        if (Gui.beginMenu("View")) {
            if (Gui.menuItem("Height map", "H", app.heightMap, true)) app.toggleHeightMap();
            if (Gui.menuItem("Reset camera", "R")) app.camera.reset();
            Gui.endMenu();
        }
        if (Gui.beginMenu("Test")) {
            if (Gui.menuItem("Play it", "")) app.playIt();
            if (Gui.menuItem("Ask a bot", "")) app.askBot();
            Gui.endMenu();
        }
        Gui.endMainMenuBar();
    }

    void toolsPanel(int fh) {
        Gui.setNextWindowPos(8, 32, GuiCond.Always);
        Gui.setNextWindowSize(300, 0, GuiCond.Always);
        Gui.setNextWindowSizeConstraints(300, 0, 300, fh - 32 - 3 * Gui.frameHeight()); // above the status line
        Gui.begin("Tools", GuiWindowFlags.NoMove | GuiWindowFlags.NoResize | GuiWindowFlags.NoCollapse);
        if (Gui.radioButton("Terrain tool", app.tool.mode() == ToolController.Mode.TERRAIN)) app.tool.setMode(ToolController.Mode.TERRAIN);
        Gui.sameLine();
        if (Gui.radioButton("Object tool", app.tool.mode() == ToolController.Mode.OBJECT)) app.tool.setMode(ToolController.Mode.OBJECT);
        Gui.textDisabled("SHIFT switches, WASD moves,");
        Gui.textDisabled("ENTER applies");
        Gui.separator();
        if (app.tool.mode() == ToolController.Mode.TERRAIN) {
            ToolController.TerrainAction[] all = ToolController.TerrainAction.values();
            for (int i = 0; i < all.length; i++) {
                if (Gui.radioButton(ACTIONS[i], app.tool.action() == all[i])) app.tool.setAction(all[i]);
                if (i % 2 == 0) Gui.sameLine(150);
            }
            Gui.separator();
            float[] rad = {(float) app.tool.radius}, str = {(float) app.tool.strength};
            if (Gui.sliderFloat("Radius m", rad, 0.05f, 3f, "%.2f")) app.tool.radius = rad[0];
            if (Gui.sliderFloat("Strength", str, 0.005f, 1f, "%.3f")) app.tool.strength = str[0];
            GuiDouble hh = new GuiDouble(app.tool.typedHeight), k = new GuiDouble(app.tool.typedKinetic), s = new GuiDouble(app.tool.typedStatic);
            if (Gui.inputDouble("Height m", hh)) app.tool.typedHeight = hh.get();
            if (Gui.inputDouble("Typed mu_k", k)) app.tool.typedKinetic = k.get();
            if (Gui.inputDouble("Typed mu_s", s)) app.tool.typedStatic = s.get();
            EditableCourse c = app.editor.course();
            int ni = c.nearestColumn(app.tool.x()), nj = c.nearestRow(app.tool.y());
            Gui.text(String.format(Locale.ROOT, "Node (%d, %d): h = %.3f m", ni, nj, c.height(ni, nj)));
            Gui.text(String.format(Locale.ROOT, "mu_k %.3f  mu_s %.3f", c.kineticFriction(ni, nj), c.staticFriction(ni, nj)));
        } else {
            int row = 0; // the row's width so far, in characters of a label plus a radio button's 4
            for (int i = 0; i < KINDS.length; i++) {
                String label = KINDS[i].label();
                label = Character.toUpperCase(label.charAt(0)) + label.substring(1);
                if (row > 0 && row + label.length() + 4 <= KIND_ROW_CHARS) Gui.sameLine();
                else row = 0;
                row += label.length() + 4;
                if (Gui.radioButton(label, app.tool.kind() == KINDS[i])) app.tool.setKind(KINDS[i]);
            }
            Gui.textDisabled("M wall, B tree, N next kind, ENTER places,");
            Gui.textDisabled("P deletes, Q/E turn");
            newObjectSettings();
        }
        Gui.separator();
        List<Obstacle> list = app.editor.course().obstacles();
        Gui.text("Objects: " + list.size() + " of at most " + app.editor.maxObstacles());
        for (int i = 0; i < list.size() && i < 200; i++) {
            Vec2 oc = ObstacleTools.center(list.get(i));
            String label = String.format(Locale.ROOT, "%d %s (%.2f, %.2f)##o%d", i, ObstacleTools.describe(list.get(i)), oc.x(), oc.y(), i);
            if (Gui.selectable(label, i == app.selected)) app.selected = i;
        }
        if (app.selected >= 0 && app.selected < list.size()) {
            if (Gui.button("Turn left")) app.editor.rotateObstacle(app.selected, ToolController.ROTATE_STEP_DEG);
            Gui.sameLine();
            if (Gui.button("Turn right")) app.editor.rotateObstacle(app.selected, -ToolController.ROTATE_STEP_DEG);
            Gui.sameLine();
            if (Gui.button("Delete")) {
                app.editor.removeObstacle(app.selected);
                app.selected = -1;
            }
            if (app.selected >= 0) selectedObjectFields(list.get(app.selected));
        }
        zoneList();
        elements.lists(app);
        Gui.end();
    }

    /** Sizes of the objects the tool will place. */
    private void newObjectSettings() {
        switch (app.tool.kind()) {
            case WALL -> {
                float[] len = {(float) app.tool.wallLength}, th = {(float) app.tool.wallThickness}, ht = {(float) app.tool.wallHeight};
                if (Gui.sliderFloat("Wall length", len, 0.2f, 5f, "%.2f")) app.tool.wallLength = len[0];
                if (Gui.sliderFloat("Thickness", th, 0f, 0.5f, "%.3f")) app.tool.wallThickness = th[0];
                if (Gui.sliderFloat("Height", ht, 0.02f, 1f, "%.2f")) app.tool.wallHeight = Math.max(0.01, ht[0]);
            }
            case TREE -> {
                float[] tr = {(float) app.tool.treeRadius}, ht = {(float) app.tool.treeHeight};
                if (Gui.sliderFloat("Tree radius", tr, 0.05f, 0.5f, "%.2f")) app.tool.treeRadius = tr[0];
                if (Gui.sliderFloat("Tree height", ht, 0.2f, 3f, "%.2f")) app.tool.treeHeight = ht[0];
            }
            case BOX -> {
                float[] bs = {(float) app.tool.boxSize}, ht = {(float) app.tool.boxHeight};
                if (Gui.sliderFloat("Box size", bs, 0.1f, 2f, "%.2f")) app.tool.boxSize = bs[0];
                if (Gui.sliderFloat("Box height", ht, 0.05f, 2f, "%.2f")) app.tool.boxHeight = ht[0];
            }
            case MODEL -> {
                List<String> models = ModelCatalog.BUNDLED;
                GuiInt choice = new GuiInt(Math.max(0, models.indexOf(app.tool.modelFile)));
                if (Gui.combo("Model", choice, models.toArray(new String[0]))) app.tool.modelFile = models.get(choice.get());
                float[] sc = {(float) app.tool.modelScale};
                if (Gui.sliderFloat("Scale", sc, 0.1f, 3f, "%.2f")) app.tool.modelScale = Math.max(0.01, sc[0]);
            }
            default -> ElementPanels.newElementSettings(app.tool);
        }
        if (!app.tool.kind().isObstacle()) return;
        float[] re = {(float) app.tool.restitution};
        if (Gui.sliderFloat("Restitution", re, 0f, 2f, "%.2f")) app.tool.restitution = re[0];
    }

    /** The selected object's sizes and restitution; a typed value is one undoable edit when the field is left. */
    private void selectedObjectFields(Obstacle o) {
        if (app.selected != selectedFieldsFor || app.editor.version() != selectedFieldsVersion) {
            selectedFieldsFor = app.selected;
            selectedFieldsVersion = app.editor.version();
            double[] v = sizes(o);
            objA.set(v[0]);
            objB.set(v[1]);
            objC.set(v[2]);
            objRestitution.set(o.restitution());
        }
        try {
            if (elements.selectedObject(app, o, objA, objB)) {
                Gui.inputDouble("Restitution", objRestitution);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setRestitution(app.selected, objRestitution.get());
                return;
            }
            if (o instanceof Obstacle.Wall) {
                Gui.inputDouble("Thickness m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setWallSize(app.selected, objA.get(), objB.get());
                Gui.inputDouble("Height m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setWallSize(app.selected, objA.get(), objB.get());
            } else if (o instanceof Obstacle.Tree) {
                Gui.inputDouble("Radius m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setTreeSize(app.selected, objA.get(), objB.get());
                Gui.inputDouble("Height m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setTreeSize(app.selected, objA.get(), objB.get());
            } else if (o instanceof Obstacle.Box) {
                Gui.inputDouble("Width m", objA);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setBoxSize(app.selected, objA.get(), objB.get(), objC.get());
                Gui.inputDouble("Depth m", objB);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setBoxSize(app.selected, objA.get(), objB.get(), objC.get());
                Gui.inputDouble("Height m", objC);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setBoxSize(app.selected, objA.get(), objB.get(), objC.get());
            } else {
                Gui.inputDouble("Scale", objA);
                if (Gui.isItemDeactivatedAfterEdit()) app.editor.setModelScale(app.selected, objA.get());
            }
            Gui.inputDouble("Restitution", objRestitution);
            if (Gui.isItemDeactivatedAfterEdit()) app.editor.setRestitution(app.selected, objRestitution.get());
        } catch (IllegalArgumentException e) {
            app.say(e.getMessage());
            selectedFieldsFor = -1; // show the object's values again
        }
    }

    /** The editable sizes of an object, in the order of its fields. */
    private static double[] sizes(Obstacle o) {
        if (o instanceof Obstacle.Moving m) return new double[]{m.motion().period(), m.motion().phase(), 0};
        if (o instanceof Obstacle.Bumper b) return new double[]{b.radius(), b.height(), 0};
        if (o instanceof Obstacle.Gate g) return new double[]{g.height(), 0, 0};
        if (o instanceof Obstacle.Wall w) return new double[]{w.thickness(), w.height(), 0};
        if (o instanceof Obstacle.Tree t) return new double[]{t.radius(), t.height(), 0};
        if (o instanceof Obstacle.Box b) {
            return new double[]{b.max().x() - b.min().x(), b.max().y() - b.min().y(), b.max().z() - b.min().z()};
        }
        return new double[]{((Obstacle.Model) o).scale(), 0, 0};
    }

    /** The course's friction zones: listed, deletable, friction editable. */
    private void zoneList() {
        List<Zone> zones = app.editor.zones();
        if (zones.isEmpty()) return;
        Gui.separator();
        Gui.text("Friction zones: " + zones.size() + " (later ones win)");
        for (int i = 0; i < zones.size(); i++) {
            if (Gui.selectable(i + " " + ZoneTools.describe(zones.get(i)) + "##z" + i, i == app.selectedZone)) {
                app.selectedZone = i;
                zoneKinetic.set(zones.get(i).kineticFriction());
                zoneStatic.set(zones.get(i).staticFriction());
            }
        }
        if (app.selectedZone < 0 || app.selectedZone >= zones.size()) return;
        Gui.textWrapped(ZoneTools.describe(zones.get(app.selectedZone))); // the list cuts long lines
        try {
            Gui.inputDouble("Zone mu_k", zoneKinetic);
            if (Gui.isItemDeactivatedAfterEdit()) app.editor.setZoneFriction(app.selectedZone, zoneKinetic.get(), zoneStatic.get());
            Gui.inputDouble("Zone mu_s", zoneStatic);
            if (Gui.isItemDeactivatedAfterEdit()) app.editor.setZoneFriction(app.selectedZone, zoneKinetic.get(), zoneStatic.get());
            if (Gui.button("Delete zone")) {
                app.editor.removeZone(app.selectedZone);
                app.selectedZone = -1;
            }
        } catch (IllegalArgumentException e) {
            app.say(e.getMessage());
            zoneKinetic.set(zones.get(app.selectedZone).kineticFriction());
            zoneStatic.set(zones.get(app.selectedZone).staticFriction());
        }
    }

    private void syncFields() {
        if (app.fieldsVersion == app.editor.version()) return;
        app.fieldsVersion = app.editor.version();
        Course c = app.editor.toCourse();
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
        maxObjects.set(app.editor.maxObstacles());
        courseName.set(c.name());
    }

    /** The Course panel's top in interface units as last drawn; very large before it was. */
    float courseTop() {
        return courseTop;
    }

    void coursePanel(int fw, int fh) {
        syncFields();
        Gui.setNextWindowPos(fw - 8, fh - 48, GuiCond.Always, 1f, 1f);
        Gui.setNextWindowSize(330, 0, GuiCond.Always);
        Gui.begin("Course", GuiWindowFlags.NoMove | GuiWindowFlags.NoCollapse);
        float[] rect = Gui.windowRect();
        if (rect[1] >= 0) courseTop = rect[1];
        try {
            Gui.inputText("Name", courseName);
            if (Gui.isItemDeactivatedAfterEdit()) app.editor.setName(courseName.get());
            Gui.inputDouble("Start x", startX);
            Gui.inputDouble("Start y", startY);
            if (Gui.button("Set start")) app.editor.setStart(startX.get(), startY.get());
            Gui.inputDouble("Hole x", holeX);
            Gui.inputDouble("Hole y", holeY);
            if (Gui.button("Set hole")) app.editor.setHole(holeX.get(), holeY.get());
            Gui.inputDouble("Hole radius", holeRadius);
            if (Gui.isItemDeactivatedAfterEdit()) app.editor.setHoleRadius(holeRadius.get());
            if (Gui.combo("Hole rule", holeRule, new String[]{"rest", "capture"})) {
                app.editor.setHoleRule(HoleRule.values()[holeRule.get()]);
            }
            Gui.separator();
            Gui.inputDouble("Gravity", gravity);
            Gui.inputDouble("mu_k", kinetic);
            Gui.inputDouble("mu_s", statics);
            Gui.inputDouble("Max speed", maxSpeed);
            if (Gui.button("Apply physics")) {
                PhysicsSettings p = app.editor.toCourse().physics();
                app.editor.setPhysics(new PhysicsSettings(gravity.get(), kinetic.get(), statics.get(), maxSpeed.get(), p.model(),
                        p.ballRadius(), p.ballMass(), p.dragCoefficient(), p.airDensity(), p.groundRestitution(), p.puttsOnly()));
            }
            if (Gui.inputInt("Max objects", maxObjects)) app.editor.setMaxObstacles(Math.max(0, maxObjects.get()));
        } catch (IllegalArgumentException e) {
            app.say(e.getMessage());
            app.fieldsVersion = -1;
        }
        Gui.separator();
        if (app.problems.isEmpty()) {
            Gui.textColored(0.5f, 1f, 0.5f, 1f, "No problems: ready to save");
        } else {
            for (Problem p : app.problems) Gui.textColored(1f, 0.4f, 0.4f, 1f, p.message());
        }
        Gui.separator();
        List<String> names = BotCatalog.names();
        Gui.setNextItemWidth(120);
        Gui.combo("##bot", app.botChoice, names.toArray(new String[0]));
        Gui.sameLine();
        if (Gui.button("Ask a bot")) app.askBot();
        Gui.sameLine();
        if (Gui.button("Play it")) app.playIt();
        if (app.botCheck != null) {
            if (!app.botCheck.isDone()) {
                Gui.text(app.botCheck.message());
                Gui.progressBar((float) app.botCheck.progress(), 200, 0);
                Gui.sameLine();
                if (Gui.button("Cancel##bot")) app.botCheck.cancel();
            } else if (app.botCheck.result() != null) Gui.text(app.botCheck.result().describe());
            else Gui.text(app.botCheck.failure());
        }
        Gui.end();
    }

    void statusLine(int fw, int fh) {
        Gui.setNextWindowPos(8, fh - 8, GuiCond.Always, 0f, 1f);
        Gui.begin("##status", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        String state = app.editor.isDirty() ? "unsaved changes" : "saved";
        String tip = String.format(Locale.ROOT, "%s | tool (%.2f, %.2f) | %s%s", state, app.tool.x(), app.tool.y(),
                app.tool.mode() == ToolController.Mode.TERRAIN ? "terrain: " + app.tool.action().label()
                        : "object: " + app.tool.kind().name().toLowerCase(Locale.ROOT),
                app.message != null ? " | " + app.message : "");
        Gui.text(tip);
        Gui.end();
    }

    void dialogs(int fw, int fh) {
        if (app.dialog == EditorApp.Dialog.NONE) return;
        Gui.setNextWindowPos(fw * 0.5f, fh * 0.5f, GuiCond.Always, 0.5f, 0.5f);
        Gui.begin("##dialog", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
        switch (app.dialog) {
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
                        app.replaceEditor(CourseEditor.create(newName.get(), newWidth.get(), newDepth.get(), newSpacing.get(),
                                newExpression.get()));
                        app.dialog = EditorApp.Dialog.NONE;
                    } catch (IllegalArgumentException e) {
                        app.say(e.getMessage());
                    }
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) app.dialog = EditorApp.Dialog.NONE;
            }
            case OPEN, SAVE_AS -> {
                Gui.text(app.dialog == EditorApp.Dialog.OPEN ? "Open course file" : "Save course as");
                Gui.setNextItemWidth(420);
                Gui.inputText("##path", app.pathField);
                if (Gui.button(app.dialog == EditorApp.Dialog.OPEN ? "Open" : "Save")) {
                    Path p = Path.of(app.pathField.get().trim());
                    if (app.dialog == EditorApp.Dialog.OPEN) {
                        try {
                            app.dialog = app.openFile(p) ? EditorApp.Dialog.RECOVERY : EditorApp.Dialog.NONE;
                        } catch (CourseException e) {
                            app.say(e.getMessage());
                        }
                    } else if (app.saveTo(p)) {
                        app.dialog = EditorApp.Dialog.NONE;
                    }
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) app.dialog = EditorApp.Dialog.NONE;
            }
            case RECOVERY -> {
                Gui.text(app.recoveryReason);
                Gui.text("Recover the unsaved course from " + app.recovery.file() + "?");
                if (Gui.button("Recover")) {
                    try {
                        app.replaceEditor(CourseEditor.recovered(app.recovery.load()));
                        app.recovery.release();
                        app.say("recovered: save it to keep it");
                    } catch (CourseException e) {
                        app.say(e.getMessage());
                    }
                    app.dialog = EditorApp.Dialog.NONE;
                }
                Gui.sameLine();
                if (Gui.button("Discard")) {
                    app.recovery.clear();
                    app.dialog = EditorApp.Dialog.NONE;
                }
            }
            case CONFIRM_CLOSE -> {
                Gui.text("The course has unsaved changes.");
                if (Gui.button("Save and close")) {
                    if (app.editor.file() == null) app.openSaveAs();
                    else if (app.saveTo(app.editor.file())) glfwSetWindowShouldClose(app.window.handle(), true);
                }
                Gui.sameLine();
                if (Gui.button("Close without saving")) {
                    app.dialog = EditorApp.Dialog.NONE;
                    app.editor.endStroke();
                    glfwSetWindowShouldClose(app.window.handle(), true);
                }
                Gui.sameLine();
                if (Gui.button("Cancel")) app.dialog = EditorApp.Dialog.NONE;
            }
            default -> {
            }
        }
        Gui.end();
    }
}
