package minigolf.editor;

/** The original editor's keys, independent of the window system (the window maps its key codes to these). */
public enum EditorKey {
    /** W / A / S / D: move the tool one grid step along +y / -x / -y / +x. */
    UP, LEFT, DOWN, RIGHT,
    /** SHIFT: switch between the object tool and the terrain tool. */
    TOGGLE_TOOL,
    /** M: the object tool places walls. */
    WALL,
    /** B: the object tool places trees. */
    TREE,
    /** N: the object tool places the next kind (wall, tree, ... windmill, push zone, magnet, teleport). */
    NEXT_KIND,
    /** ENTER: place the object, or apply the terrain tool, at the tool's position. */
    PLACE,
    /** P: delete the object under the tool, or with the terrain tool the terrain cell under it. */
    DELETE,
    /** Q / E: turn the object under the tool by 15 degrees counter-clockwise / clockwise. */
    ROTATE_LEFT, ROTATE_RIGHT,
    /** Ctrl+Z / Ctrl+Y. */
    UNDO, REDO
}
