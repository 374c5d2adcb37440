package minigolf.editor.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.course.Magnet;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.editor.CourseEditor;
import minigolf.editor.ToolController;
import minigolf.ui.Gui;
import minigolf.ui.GuiDouble;

/**
 * The Objects panel's part for the elements of issue 24: what a new bumper, gate, windmill, turning
 * bar, sliding gate, push zone, magnet or teleport will be; the selected moving obstacle's period
 * and phase, a bumper's size, a gate's direction; and the lists of push zones, magnets and teleports
 * (selectable, editable, movable to the tool, deletable), each change one undoable edit.
 */
final class ElementPanels {
    private final GuiDouble a = new GuiDouble(), b = new GuiDouble(), c = new GuiDouble();
    private int fieldsFor = -1;
    private long fieldsVersion = -1;

    /** Sliders for what the tool places next (kinds beyond wall, tree, box and model). */
    static void newElementSettings(ToolController t) {
        switch (t.kind()) {
            case BUMPER -> {
                float[] r = {(float) t.bumperRadius}, e = {(float) t.bumperRestitution};
                if (Gui.sliderFloat("Bumper radius", r, 0.03f, 0.5f, "%.2f")) t.bumperRadius = r[0];
                if (Gui.sliderFloat("Kick (restitution)", e, 0f, 2f, "%.2f")) t.bumperRestitution = e[0];
            }
            case GATE -> {
                float[] l = {(float) t.gateLength};
                if (Gui.sliderFloat("Gate length", l, 0.1f, 3f, "%.2f")) t.gateLength = l[0];
                Gui.textDisabled("passes to +x; Flip in its fields");
            }
            case WINDMILL, TURNING_BAR, SLIDING_GATE -> {
                float[] p = {(float) t.motionPeriod};
                if (Gui.sliderFloat("Period s", p, 0.5f, 12f, "%.1f")) t.motionPeriod = p[0];
                if (t.kind() == ToolController.ObjectKind.WINDMILL) {
                    float[] h = {(float) t.windmillHub};
                    if (Gui.sliderFloat("Hub height", h, 0.45f, 1f, "%.2f")) t.windmillHub = h[0];
                }
            }
            case PUSH_ZONE -> {
                float[] s = {(float) t.pushSize}, f = {(float) t.pushStrength}, d = {(float) t.pushDirectionDeg};
                if (Gui.sliderFloat("Zone size", s, 0.2f, 4f, "%.2f")) t.pushSize = s[0];
                if (Gui.sliderFloat("Push m/s^2", f, 0f, 5f, "%.2f")) t.pushStrength = f[0];
                if (Gui.sliderFloat("Direction deg", d, -180f, 180f, "%.0f")) t.pushDirectionDeg = d[0];
            }
            case MAGNET -> {
                float[] r = {(float) t.magnetRadius}, s = {(float) t.magnetStrength};
                if (Gui.sliderFloat("Magnet radius", r, 0.1f, 3f, "%.2f")) t.magnetRadius = r[0];
                if (Gui.sliderFloat("Pull m/s^2 (<0 repels)", s, -10f, 10f, "%.1f")) t.magnetStrength = s[0];
            }
            case TELEPORT -> {
                float[] r = {(float) t.teleportRadius}, x = {(float) t.exitDx}, y = {(float) t.exitDy};
                if (Gui.sliderFloat("Entry radius", r, 0.05f, 1f, "%.2f")) t.teleportRadius = r[0];
                if (Gui.sliderFloat("Exit dx", x, -10f, 10f, "%.2f")) t.exitDx = x[0];
                if (Gui.sliderFloat("Exit dy", y, -10f, 10f, "%.2f")) t.exitDy = y[0];
            }
            default -> {
            }
        }
    }

    /**
     * The selected object's fields when it is an element (a moving obstacle, a bumper, a gate);
     * false for the other obstacles, whose fields the caller draws. {@code first} and {@code second}
     * hold the values shown (see EditorPanels.sizes).
     */
    boolean selectedObject(EditorApp app, Obstacle o, GuiDouble first, GuiDouble second) {
        CourseEditor editor = app.editor;
        if (o instanceof Obstacle.Moving m) {
            String how = m.motion() instanceof Motion.Rotate ? "turns" : m.motion() instanceof Motion.Swing ? "swings" : "slides";
            Gui.textDisabled(ObjectsText.motion(m.motion(), how));
            Gui.inputDouble("Period s", first);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setMotionTiming(app.selected, first.get(), second.get());
            Gui.inputDouble("Phase s", second);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setMotionTiming(app.selected, first.get(), second.get());
            return true;
        }
        if (o instanceof Obstacle.Bumper) {
            Gui.inputDouble("Radius m", first);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setBumperSize(app.selected, first.get(), second.get());
            Gui.inputDouble("Height m", second);
            if (Gui.isItemDeactivatedAfterEdit()) editor.setBumperSize(app.selected, first.get(), second.get());
            return true;
        }
        if (o instanceof Obstacle.Gate g) {
            Vec2 n = g.passNormal();
            Gui.textDisabled(String.format(Locale.ROOT, "passes towards (%.2f, %.2f)", n.x(), n.y()));
            if (Gui.button("Flip direction")) editor.flipGate(app.selected);
            return true;
        }
        return false;
    }

    /** The push zones, magnets and teleports, as one list: select one to edit, move or delete it. */
    void lists(EditorApp app) {
        CourseEditor editor = app.editor;
        List<PushZone> pushes = editor.pushZones();
        List<Magnet> magnets = editor.magnets();
        List<Teleport> teleports = editor.teleports();
        int total = pushes.size() + magnets.size() + teleports.size();
        if (total == 0) return;
        Gui.separator();
        Gui.text("Push zones " + pushes.size() + ", magnets " + magnets.size() + ", teleports " + teleports.size());
        List<String> labels = new ArrayList<>();
        for (PushZone z : pushes) labels.add(String.format(Locale.ROOT, "push (%.1f, %.1f) m/s^2", z.push().x(), z.push().y()));
        for (Magnet m : magnets) labels.add(String.format(Locale.ROOT, "magnet %.1f at (%.2f, %.2f)", m.strength(), m.position().x(), m.position().y()));
        for (Teleport t : teleports) labels.add("teleport, " + t.exits().size() + " exit" + (t.exits().size() > 1 ? "s" : ""));
        for (int i = 0; i < labels.size(); i++) {
            if (Gui.selectable(i + " " + labels.get(i) + "##e" + i, i == app.selectedElement)) app.selectedElement = i;
        }
        int k = app.selectedElement;
        if (k < 0 || k >= total) return;
        if (k != fieldsFor || editor.version() != fieldsVersion) {
            fieldsFor = k;
            fieldsVersion = editor.version();
            if (k < pushes.size()) {
                a.set(pushes.get(k).push().x());
                b.set(pushes.get(k).push().y());
            } else if (k < pushes.size() + magnets.size()) {
                Magnet m = magnets.get(k - pushes.size());
                a.set(m.strength());
                b.set(m.radius());
            } else {
                Teleport.Exit e = teleports.get(k - pushes.size() - magnets.size()).exits().get(0);
                c.set(e.directionDeg() == null ? Double.NaN : e.directionDeg());
            }
        }
        double tx = app.tool.x(), ty = app.tool.y();
        try {
            if (k < pushes.size()) {
                PushZone z = pushes.get(k);
                Gui.inputDouble("Push x", a);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setPushZone(k, new PushZone(z.shape(), new Vec2(a.get(), b.get())));
                Gui.inputDouble("Push y", b);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setPushZone(k, new PushZone(z.shape(), new Vec2(a.get(), b.get())));
                if (Gui.button("Move to tool")) editor.setPushZone(k, new PushZone(ObjectsText.moved(z.shape(), tx, ty), z.push()));
                Gui.sameLine();
                if (Gui.button("Delete push zone")) {
                    editor.setPushZone(k, null);
                    app.selectedElement = -1;
                }
            } else if (k < pushes.size() + magnets.size()) {
                int j = k - pushes.size();
                Magnet m = magnets.get(j);
                Gui.inputDouble("Strength m/s^2", a);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setMagnet(j, new Magnet(m.position(), b.get(), a.get()));
                Gui.inputDouble("Radius m", b);
                if (Gui.isItemDeactivatedAfterEdit()) editor.setMagnet(j, new Magnet(m.position(), b.get(), a.get()));
                if (Gui.button("Move to tool")) editor.setMagnet(j, new Magnet(new Vec2(tx, ty), m.radius(), m.strength()));
                Gui.sameLine();
                if (Gui.button("Delete magnet")) {
                    editor.setMagnet(j, null);
                    app.selectedElement = -1;
                }
            } else {
                int j = k - pushes.size() - magnets.size();
                Teleport t = teleports.get(j);
                Gui.textDisabled("exit direction deg (blank: the ball keeps its own)");
                Gui.inputDouble("Exit direction", c);
                if (Gui.isItemDeactivatedAfterEdit()) {
                    Teleport.Exit e = t.exits().get(0);
                    List<Teleport.Exit> exits = new ArrayList<>(t.exits());
                    exits.set(0, new Teleport.Exit(e.position(), Double.isFinite(c.get()) ? c.get() : null));
                    editor.setTeleport(j, new Teleport(t.entry(), exits, t.seed()));
                }
                if (Gui.button("Entry to tool")) editor.setTeleport(j, new Teleport(ObjectsText.moved(t.entry(), tx, ty), t.exits(), t.seed()));
                Gui.sameLine();
                if (Gui.button("Exit to tool")) {
                    List<Teleport.Exit> exits = new ArrayList<>(t.exits());
                    exits.set(0, new Teleport.Exit(new Vec2(tx, ty), t.exits().get(0).directionDeg()));
                    editor.setTeleport(j, new Teleport(t.entry(), exits, t.seed()));
                }
                if (Gui.button("Delete teleport")) {
                    editor.setTeleport(j, null);
                    app.selectedElement = -1;
                }
            }
        } catch (IllegalArgumentException e) {
            app.say(e.getMessage());
            fieldsFor = -1;
        }
    }

    /** Short descriptions and shape moves for the panel. */
    static final class ObjectsText {
        private ObjectsText() {
        }

        static String motion(Motion m, String how) {
            return String.format(Locale.ROOT, "%s once every %.2f s (phase %.2f s)", how, m.period(), m.phase());
        }

        /** The shape moved so that its centre is at (x, y). */
        static Shape moved(Shape s, double x, double y) {
            if (s instanceof Shape.Circle circle) return new Shape.Circle(new Vec2(x, y), circle.radius());
            if (s instanceof Shape.Rect r) {
                double hx = (r.max().x() - r.min().x()) / 2, hy = (r.max().y() - r.min().y()) / 2;
                return new Shape.Rect(new Vec2(x - hx, y - hy), new Vec2(x + hx, y + hy));
            }
            if (s instanceof Shape.Cells c) {
                // The grid moved with its cells, the centre of the cells' box to (x, y).
                double[] box = minigolf.physics.ShapeBoxes.of(c);
                double dx = x - (box[0] + box[2]) / 2, dy = y - (box[1] + box[3]) / 2;
                return new Shape.Cells(new Vec2(c.origin().x() + dx, c.origin().y() + dy), c.size(), c.columns(), c.rows(), c.spans());
            }
            List<Vec2> points = ((Shape.Polygon) s).points();
            double cx = 0, cy = 0;
            for (Vec2 p : points) {
                cx += p.x() / points.size();
                cy += p.y() / points.size();
            }
            List<Vec2> moved = new ArrayList<>();
            for (Vec2 p : points) moved.add(new Vec2(p.x() - cx + x, p.y() - cy + y));
            return new Shape.Polygon(moved);
        }
    }
}
