package minigolf.editor;

import minigolf.course.Obstacle;

/** Adds, replaces (move, rotate) or removes the obstacle at one index of the list. */
final class ObstacleEdit implements Edit {
    private final int index;
    /** null: the obstacle did not exist before (an add). */
    private final Obstacle before;
    /** null: the obstacle is removed. */
    private final Obstacle after;
    private final String label;

    ObstacleEdit(int index, Obstacle before, Obstacle after, String label) {
        this.index = index;
        this.before = before;
        this.after = after;
        this.label = label;
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        set(c, before, after);
        changes.obstacles();
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        set(c, after, before);
        changes.obstacles();
    }

    private void set(EditableCourse c, Obstacle from, Obstacle to) {
        if (from == null) c.obstacles.add(index, to);
        else if (to == null) c.obstacles.remove(index);
        else c.obstacles.set(index, to);
    }

    @Override
    public String label() {
        return label;
    }
}
