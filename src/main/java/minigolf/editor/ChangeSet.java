package minigolf.editor;

/**
 * What changed since the view last looked: a rectangle of grid nodes (for a partial mesh update),
 * the obstacles, and anything else that needs a full rebuild of the scene (deleted cells, physics,
 * start, hole). The window takes and clears it once a frame.
 */
public final class ChangeSet {
    private int minI = Integer.MAX_VALUE, minJ = Integer.MAX_VALUE, maxI = -1, maxJ = -1;
    private boolean obstacles, structure, any;

    void nodes(int i0, int j0, int i1, int j1) {
        minI = Math.min(minI, i0);
        minJ = Math.min(minJ, j0);
        maxI = Math.max(maxI, i1);
        maxJ = Math.max(maxJ, j1);
        any = true;
    }

    void obstacles() {
        obstacles = true;
        any = true;
    }

    void structure() {
        structure = true;
        any = true;
    }

    public boolean isEmpty() {
        return !any;
    }

    /** Whether some grid nodes changed; their range is {@link #nodeRange()}. */
    public boolean hasNodes() {
        return maxI >= 0;
    }

    /** {minI, minJ, maxI, maxJ}, inclusive node indices. */
    public int[] nodeRange() {
        return new int[]{minI, minJ, maxI, maxJ};
    }

    public boolean obstaclesChanged() {
        return obstacles;
    }

    /** Deleted cells, start, hole or physics changed: rebuild the whole scene. */
    public boolean structureChanged() {
        return structure;
    }

    /** A copy of what is recorded, and this set emptied. */
    public ChangeSet take() {
        ChangeSet copy = new ChangeSet();
        copy.minI = minI;
        copy.minJ = minJ;
        copy.maxI = maxI;
        copy.maxJ = maxJ;
        copy.obstacles = obstacles;
        copy.structure = structure;
        copy.any = any;
        minI = minJ = Integer.MAX_VALUE;
        maxI = maxJ = -1;
        obstacles = structure = any = false;
        return copy;
    }
}
