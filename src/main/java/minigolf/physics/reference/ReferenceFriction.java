package minigolf.physics.reference;

import java.util.List;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Zone;
import minigolf.physics.FrictionField;
import minigolf.physics.World;

/**
 * Kinetic friction for the integrator with the zone held fixed for a whole stretch of path: inside
 * a step the friction of the zone the ball is in is continued smoothly past the zone's edge, and
 * the simulator restarts the integration at the edge with the next zone. So friction never jumps
 * inside a step and the error control stays honest. Static friction (used only at rest points) and
 * zone membership are looked up in the course's {@link FrictionField}.
 */
final class ReferenceFriction {
    private final FrictionField field;
    private final List<Zone> zones;
    private final double defaultKinetic;
    private final TerrainSpec.HeightGrid grid;
    private int zone = -1;

    ReferenceFriction(World world) {
        this.field = world.friction();
        this.zones = world.course().zones();
        PhysicsSettings physics = world.physics();
        this.defaultKinetic = physics.kineticFriction();
        this.grid = world.course().terrain() instanceof TerrainSpec.HeightGrid g && g.kineticFriction() != null ? g : null;
    }

    boolean hasZones() {
        return !zones.isEmpty();
    }

    int zoneAt(double x, double y) {
        return zones.isEmpty() ? -1 : field.zoneAt(x, y);
    }

    /** Holds the zone whose friction the integrator uses until the next call (-1: outside every zone). */
    void holdZone(int newZone) {
        zone = newZone;
    }

    int heldZone() {
        return zone;
    }

    /** μk under the held zone, continued past its edge. */
    double kinetic(double x, double y) {
        if (zone >= 0) return zones.get(zone).kineticFriction();
        return grid != null ? bilinear(grid.kineticFriction(), x, y) : defaultKinetic;
    }

    /** max(μs, μk) at a rest point, as the "Coming to rest" rule asks. */
    double holding(double x, double y) {
        return Math.max(field.staticFriction(x, y), field.kinetic(x, y));
    }

    /** The grid's per-node friction, bilinear between nodes and clamped at the grid's edge (course-format.md). */
    private double bilinear(double[][] nodes, double x, double y) {
        int rows = nodes.length, columns = nodes[0].length;
        double u = clamp((x - grid.origin().x()) / grid.spacing(), columns - 1);
        double v = clamp((y - grid.origin().y()) / grid.spacing(), rows - 1);
        int i = Math.min((int) Math.floor(u), columns - 2), j = Math.min((int) Math.floor(v), rows - 2);
        double tx = u - i, ty = v - j;
        double low = nodes[j][i] + tx * (nodes[j][i + 1] - nodes[j][i]);
        double high = nodes[j + 1][i] + tx * (nodes[j + 1][i + 1] - nodes[j + 1][i]);
        return low + ty * (high - low);
    }

    private static double clamp(double u, double max) {
        return u < 0 ? 0 : Math.min(u, max);
    }
}
