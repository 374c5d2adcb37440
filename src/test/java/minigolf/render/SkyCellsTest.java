package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.*;

/** Which sky cells may show clouds (plain geometry, no GL). */
class SkyCellsTest {
    static final int CELLS = SkyPass.GRID_X * SkyPass.GRID_Y;

    static int cloudyCells(float pitchDegrees) {
        // A camera at the origin looking along +y, pitched up (positive) or down (negative).
        double p = Math.toRadians(pitchDegrees);
        Matrix4f vp = new Matrix4f().perspective((float) Math.toRadians(45), 16f / 9, 0.1f, 100f)
                .lookAt(0, 0, 0, 0, (float) Math.cos(p), (float) Math.sin(p), 0, 0, 1);
        int[] order = new int[CELLS * 6];
        int cloudy = SkyPass.sortCells(vp.invert(new Matrix4f()), new float[(SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1)],
                order, new Vector4f(), new Vector4f());
        // Every cell appears once: the two parts together are a permutation of the grid's triangles.
        int[] sorted = order.clone();
        Arrays.sort(sorted);
        assertEquals(0, sorted[0]);
        assertEquals((SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1) - 1, sorted[sorted.length - 1]);
        assertEquals(0, cloudy % 6);
        return cloudy / 6;
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
