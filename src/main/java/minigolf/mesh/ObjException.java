package minigolf.mesh;

/** A .obj file could not be read or parsed. The message is one line: {@code line N: problem} or a read error. */
public final class ObjException extends Exception {
    private static final long serialVersionUID = 1L;
    private final int line;

    public ObjException(int line, String problem) {
        super(line > 0 ? "line " + line + ": " + problem : problem);
        this.line = line;
    }

    /** The 1-based line number the problem is on, or 0 when it is not about one line. */
    public int line() {
        return line;
    }
}
