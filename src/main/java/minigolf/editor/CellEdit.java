package minigolf.editor;

/** Deletes or restores terrain cells (a deleted cell is out of bounds). */
final class CellEdit implements Edit {
    private final int[] cells;
    private final boolean[] before;
    private final boolean deleted;

    /** Cells given as indices j * (columns - 1) + i; {@code deleted}: the state they get. */
    CellEdit(EditableCourse course, int[] cells, boolean deleted) {
        this.cells = cells.clone();
        this.before = new boolean[cells.length];
        for (int n = 0; n < cells.length; n++) before[n] = course.deleted[cells[n]];
        this.deleted = deleted;
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        for (int cell : cells) c.deleted[cell] = deleted;
        changes.structure();
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        for (int n = 0; n < cells.length; n++) c.deleted[cells[n]] = before[n];
        changes.structure();
    }

    @Override
    public String label() {
        return (deleted ? "delete " : "restore ") + (cells.length == 1 ? "cell" : cells.length + " cells");
    }
}
