package minigolf.physics;

import java.util.List;
import minigolf.course.PhysicsSettings;
import minigolf.course.Shape;
import minigolf.course.TerrainSpec;
import minigolf.course.Zone;

/**
 * Friction under the ball: the last zone containing the point wins, else the grid's per-node
 * friction (bilinear between nodes, clamped at the edges), else the course's physics values.
 */
public final class FrictionField {
    private final double defaultKinetic;
    private final double defaultStatic;
    private final Zone[] zones;
    private final TerrainSpec.HeightGrid grid;
    private final boolean uniform;
    /** Each zone's bounding box: minX, minY, maxX, maxY. */
    private final double[] boxes;
    private final boolean hazards;

    public FrictionField(PhysicsSettings physics, List<Zone> zones, TerrainSpec terrain) {
        this.defaultKinetic = physics.kineticFriction();
        this.defaultStatic = physics.staticFriction();
        this.zones = zones.toArray(new Zone[0]);
        this.grid = terrain instanceof TerrainSpec.HeightGrid g
                && (g.kineticFriction() != null || g.staticFriction() != null) ? g : null;
        this.uniform = this.zones.length == 0 && grid == null;
        this.boxes = new double[4 * this.zones.length];
        for (int k = 0; k < this.zones.length; k++) box(this.zones[k].shape(), k);
        boolean any = false;
        for (Zone z : this.zones) any |= z.hazard() != null;
        this.hazards = any;
    }

    private void box(Shape shape, int k) {
        System.arraycopy(ShapeBoxes.of(shape), 0, boxes, 4 * k, 4);
    }

    /**
     * Whether friction may change inside the rectangle: a zone's edge may cross it (its bounding
     * box meets the rectangle, which does not lie inside a rectangular or round zone), or the
     * grid gives friction per node. False means one friction everywhere in it.
     */
    public boolean mayChangeWithin(double minX, double minY, double maxX, double maxY) {
        if (grid != null) return true;
        double[] b = boxes;
        for (int k = 0; k < zones.length; k++) {
            if (b[4 * k] > maxX || b[4 * k + 2] < minX || b[4 * k + 1] > maxY || b[4 * k + 3] < minY) continue;
            if (!ShapeBoxes.covers(zones[k].shape(), minX, minY, maxX, maxY)) return true;
        }
        return false;
    }

    /** Whether some zone is a hazard (water or acid drawn as a zone). */
    public boolean hasHazards() {
        return hazards;
    }

    /**
     * The hazard of the zone that decides the friction at (x, y), or null (a zone without one
     * laid over a hazard is a bridge).
     */
    public Zone.Hazard hazardAt(double x, double y) {
        if (!hazards) return null;
        int zone = zoneAt(x, y);
        return zone >= 0 ? zones[zone].hazard() : null;
    }

    /** Whether the ball entering (x, y) ends its stroke in a hazard zone. */
    public boolean entersHazard(double x, double y) {
        Zone.Hazard h = hazardAt(x, y);
        return h != null && h.when() == Zone.Hazard.When.ENTER;
    }

    /** Whether a ball coming to rest at (x, y) ends its stroke in a hazard zone (any hazard: one it rests in it touches). */
    public boolean restsInHazard(double x, double y) {
        return hazardAt(x, y) != null;
    }

    /** Whether friction can jump somewhere (zone edges), so that strokes must split steps there. */
    public boolean hasZones() {
        return zones.length > 0;
    }

    /** The index of the zone that decides the friction at (x, y), or -1 outside every zone. */
    public int zoneAt(double x, double y) {
        for (int k = zones.length - 1; k >= 0; k--) {
            if (zones[k].shape().contains(x, y)) return k;
        }
        return -1;
    }

    public double kinetic(double x, double y) {
        if (uniform) return defaultKinetic;
        int zone = zoneAt(x, y);
        if (zone >= 0) return zones[zone].kineticFriction();
        return grid != null && grid.kineticFriction() != null
                ? bilinear(grid.kineticFriction(), x, y) : defaultKinetic;
    }

    public double staticFriction(double x, double y) {
        if (uniform) return defaultStatic;
        int zone = zoneAt(x, y);
        if (zone >= 0) return zones[zone].staticFriction();
        return grid != null && grid.staticFriction() != null
                ? bilinear(grid.staticFriction(), x, y) : defaultStatic;
    }

    private double bilinear(double[][] nodes, double x, double y) {
        int rows = nodes.length, columns = nodes[0].length;
        double u = Math.max(0, Math.min(columns - 1, (x - grid.origin().x()) / grid.spacing()));
        double v = Math.max(0, Math.min(rows - 1, (y - grid.origin().y()) / grid.spacing()));
        int i = Math.min((int) u, columns - 2), j = Math.min((int) v, rows - 2);
        double tx = u - i, ty = v - j;
        double bottom = nodes[j][i] * (1 - tx) + nodes[j][i + 1] * tx;
        double top = nodes[j + 1][i] * (1 - tx) + nodes[j + 1][i + 1] * tx;
        return bottom * (1 - ty) + top * ty;
    }
}
