package minigolf.editor;

import java.util.List;
import java.util.function.Consumer;
import java.util.function.Function;
import minigolf.course.Obstacle;
import minigolf.course.Zone;

/**
 * Adds, replaces or removes the item at one index of one of the course's lists (obstacles,
 * friction zones). {@code before} null means an add, {@code after} null a removal.
 */
final class ListItemEdit<T> implements Edit {
    private final Function<EditableCourse, List<T>> list;
    /** What the renderer and physics must refresh after the edit. */
    private final Consumer<ChangeSet> notify;
    private final int index;
    private final T before, after;
    private final String label;

    private ListItemEdit(Function<EditableCourse, List<T>> list, Consumer<ChangeSet> notify, int index, T before,
                         T after, String label) {
        this.list = list;
        this.notify = notify;
        this.index = index;
        this.before = before;
        this.after = after;
        this.label = label;
    }

    static ListItemEdit<Obstacle> obstacle(int index, Obstacle before, Obstacle after, String label) {
        return new ListItemEdit<>(c -> c.obstacles, ChangeSet::obstacles, index, before, after, label);
    }

    /** A push zone, a magnet or a teleport: drawn by the elements' pass, refreshed with the obstacles. */
    static <E> ListItemEdit<E> element(Function<EditableCourse, List<E>> list, int index, E before, E after, String label) {
        return new ListItemEdit<>(list, ChangeSet::obstacles, index, before, after, label);
    }

    /** Friction colours the terrain and changes the physics: the scene is rebuilt. */
    static ListItemEdit<Zone> zone(int index, Zone before, Zone after, String label) {
        return new ListItemEdit<>(c -> c.zones, ChangeSet::structure, index, before, after, label);
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        set(list.apply(c), before, after);
        notify.accept(changes);
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        set(list.apply(c), after, before);
        notify.accept(changes);
    }

    private void set(List<T> items, T from, T to) {
        if (from == null) items.add(index, to);
        else if (to == null) items.remove(index);
        else items.set(index, to);
    }

    @Override
    public String label() {
        return label;
    }
}
