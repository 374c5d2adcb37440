package minigolf.editor;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * Unlimited undo and redo within the session. A new edit clears the redo stack. The history also
 * knows whether the course differs from the last saved state: the saved point is an edit count,
 * so undoing back to it makes the course clean again.
 */
final class EditHistory {
    private final Deque<Edit> undo = new ArrayDeque<>();
    private final Deque<Edit> redo = new ArrayDeque<>();
    /** How many edits are applied now, and how many were applied at the last save (-1: unreachable). */
    private int applied, savedAt;

    /** Records an edit that is already applied. */
    void push(Edit edit) {
        undo.push(edit);
        redo.clear();
        if (savedAt > applied) savedAt = -1; // the saved state was in the redo stack: gone for good
        applied++;
    }

    Edit undo(EditableCourse course, ChangeSet changes) {
        if (undo.isEmpty()) return null;
        Edit e = undo.pop();
        e.revert(course, changes);
        redo.push(e);
        applied--;
        return e;
    }

    Edit redo(EditableCourse course, ChangeSet changes) {
        if (redo.isEmpty()) return null;
        Edit e = redo.pop();
        e.apply(course, changes);
        undo.push(e);
        applied++;
        return e;
    }

    boolean canUndo() {
        return !undo.isEmpty();
    }

    boolean canRedo() {
        return !redo.isEmpty();
    }

    String undoLabel() {
        return undo.isEmpty() ? null : undo.peek().label();
    }

    String redoLabel() {
        return redo.isEmpty() ? null : redo.peek().label();
    }

    int size() {
        return undo.size();
    }

    void markSaved() {
        savedAt = applied;
    }

    /** The course differs from every file (e.g. it was recovered after a crash). */
    void markUnsaved() {
        savedAt = -1;
    }

    boolean isDirty() {
        return savedAt != applied;
    }
}
