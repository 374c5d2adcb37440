package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** A deleted grid cell is out of bounds, located exactly as the edge of the bounds is. */
public class DeletedCellsTest {
    /** A flat 10 x 4 m grid (1 m cells) at h = 0.1, mu_k 0.1; column {@code deletedColumn} of cells removed (-1: none). */
    public static Course flat(int deletedColumn, double maxX) {
        double[][] h = new double[5][11];
        for (double[] row : h) java.util.Arrays.fill(row, 0.1);
        boolean[][] mask = null;
        if (deletedColumn >= 0) {
            mask = new boolean[4][10];
            for (boolean[] row : mask) row[deletedColumn] = true;
        }
        return new Course(1, "cells", new TerrainSpec.HeightGrid(new Vec2(0, 0), 1, h, null, null, mask),
                new Bounds(0, 0, maxX, 4), new PhysicsSettings(9.81, 0.1, 0.2, 5, PhysicsModel.CLASSIC),
                new Vec2(1, 2), new Hole(new Vec2(9, 2), 0.1, HoleRule.REST, null), List.of());
    }

    @Test
    void aBallRollingIntoADeletedCellIsOutWhereItCrossesTheCellEdge() {
        ShotResult viaCell = new Simulator(World.of(flat(6, 10)), SimulationSettings.DEFAULT).simulate(1, 2, 5, 0);
        ShotResult viaBounds = new Simulator(World.of(flat(-1, 6)), SimulationSettings.DEFAULT).simulate(1, 2, 5, 0);
        assertEquals(Outcome.OUT, viaCell.outcome());
        assertEquals(6.0, viaCell.endX(), 1e-6);
        assertEquals(2.0, viaCell.endY(), 1e-12);
        // The same bisection: the same crossing and time.
        assertEquals(viaBounds.endX(), viaCell.endX(), 1e-9);
        assertEquals(viaBounds.time(), viaCell.time(), 1e-9);
        // Closed form for the time to reach x = 6 (5 m at 5 m/s, deceleration 0.981): t = (5 - sqrt(25 - 2*0.981*5)) / 0.981.
        assertEquals((5 - Math.sqrt(25 - 2 * 0.981 * 5)) / 0.981, viaCell.time(), 1e-6);
    }

    @Test
    void aBallThatStopsBeforeTheDeletedCellIsUnaffected() {
        ShotResult r = new Simulator(World.of(flat(8, 10)), SimulationSettings.DEFAULT).simulate(1, 2, 3, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(1 + 9.0 / (2 * 0.981), r.endX(), 1e-4);
    }

    @Test
    void thePlayAreaExcludesExactlyTheDeletedCells() {
        PlayArea area = World.of(flat(6, 10)).playArea();
        assertTrue(area.hasDeletedCells());
        assertTrue(area.contains(5.999, 1));
        assertFalse(area.contains(6.0, 1));
        assertFalse(area.contains(6.5, 3.9));
        assertTrue(area.contains(7.0, 1)); // the far edge belongs to the next (kept) cell
        assertFalse(area.contains(10.5, 1)); // outside the bounds as before
        assertFalse(World.of(flat(-1, 10)).playArea().hasDeletedCells());
    }
}
