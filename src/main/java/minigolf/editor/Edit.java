package minigolf.editor;

/**
 * One undoable change of an {@link EditableCourse}. {@link #apply} and {@link #revert} must be
 * exact inverses: revert after apply leaves the course bit for bit as it was.
 */
public interface Edit {
    void apply(EditableCourse course, ChangeSet changes);

    void revert(EditableCourse course, ChangeSet changes);

    /** What the edit did, for the undo menu: "raise brush", "move wall". */
    String label();
}
