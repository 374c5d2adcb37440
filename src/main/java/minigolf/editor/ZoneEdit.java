package minigolf.editor;

import minigolf.course.Zone;

/** Replaces or removes the friction zone at one index of the list (null before: an add). */
final class ZoneEdit implements Edit {
    private final int index;
    private final Zone before, after;
    private final String label;

    ZoneEdit(int index, Zone before, Zone after, String label) {
        this.index = index;
        this.before = before;
        this.after = after;
        this.label = label;
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        set(c, before, after);
        changes.structure(); // friction colours the terrain and changes the physics: rebuild
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        set(c, after, before);
        changes.structure();
    }

    private void set(EditableCourse c, Zone from, Zone to) {
        if (from == null) c.zones.add(index, to);
        else if (to == null) c.zones.remove(index);
        else c.zones.set(index, to);
    }

    @Override
    public String label() {
        return label;
    }
}
