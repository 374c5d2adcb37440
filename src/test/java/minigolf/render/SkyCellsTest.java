package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.*;

/** Which sky cells may show clouds (plain geometry, no GL). */
class SkyCellsTest {
    static final int CELLS = SkyPass.GRID_X * SkyPass.GRID_Y;

    static final Vector3f BEHIND = new Vector3f(0, -1, 0.2f).normalize();

    static int cloudyCells(float pitchDegrees) {
        return cells(pitchDegrees, BEHIND)[1] + cells(pitchDegrees, BEHIND)[3];
    }

    /** Cells per group (bit 0 cloudy, bit 1 near the sun) for a camera at the origin looking along +y, pitched up (positive) or down. */
    static int[] cells(float pitchDegrees, Vector3f toSun) {
        double p = Math.toRadians(pitchDegrees);
        Matrix4f vp = new Matrix4f().perspective((float) Math.toRadians(45), 16f / 9, 0.1f, 100f)
                .lookAt(0, 0, 0, 0, (float) Math.cos(p), (float) Math.sin(p), 0, 0, 1);
        int[] order = new int[CELLS * 6];
        int corners = (SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1);
        int[] counts = SkyPass.sortCells(vp.invert(new Matrix4f()), toSun, new float[corners], new float[corners],
                order, new Vector4f(), new Vector4f());
        // Every cell appears once: the two parts together are a permutation of the grid's triangles.
        int[] sorted = order.clone();
        Arrays.sort(sorted);
        assertEquals(0, sorted[0]);
        assertEquals((SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1) - 1, sorted[sorted.length - 1]);
        int[] cells = new int[4];
        for (int g = 0; g < 4; g++) {
            assertEquals(0, counts[g] % 6);
            cells[g] = counts[g] / 6;
        }
        assertEquals(CELLS, cells[0] + cells[1] + cells[2] + cells[3]);
        return cells;
    }

    @Test
    void onlyCellsNearTheSunDrawItsDisc() {
        // The sun behind the camera: no cell near it.
        int[] away = cells(10, BEHIND);
        assertEquals(0, away[2] + away[3]);
        // The sun straight ahead, 10 degrees up, looking 10 degrees up: it sits at the screen's centre,
        // where four cells meet; the cells within 12 degrees of it are a handful, all above the horizon.
        Vector3f ahead = new Vector3f(0, (float) Math.cos(Math.toRadians(10)), (float) Math.sin(Math.toRadians(10)));
        int[] facing = cells(10, ahead);
        assertEquals(0, facing[2], "a cell near the sun below the horizon");
        assertTrue(facing[3] >= 4 && facing[3] < CELLS / 4, "cells near the sun: " + facing[3]);
    }

    @Test
    void lookingDownShowsNoCloudyCell() {
        assertEquals(0, cloudyCells(-40));
    }

    @Test
    void lookingUpMakesEveryCellCloudy() {
        assertEquals(CELLS, cloudyCells(40));
    }

    @Test
    void levelViewSplitsAtTheHorizonRow() {
        // Looking level, the horizon is the screen's middle row of corners: the upper half of the
        // cells reach above it (and the row touching it from below has corners at exactly 0: clear).
        assertEquals(CELLS / 2, cloudyCells(0));
        int slightlyDown = cloudyCells(-5);
        assertTrue(slightlyDown > 0 && slightlyDown < CELLS / 2, "cells: " + slightlyDown);
    }
}
