package minigolf.editor;

/** Changes the course's name, start, hole or physics (one record, old and new). */
final class PropertiesEdit implements Edit {
    private final EditableCourse.Properties before, after;
    private final String label;

    PropertiesEdit(EditableCourse.Properties before, EditableCourse.Properties after, String label) {
        this.before = before;
        this.after = after;
        this.label = label;
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        c.properties = after;
        changes.structure();
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        c.properties = before;
        changes.structure();
    }

    @Override
    public String label() {
        return label;
    }
}
