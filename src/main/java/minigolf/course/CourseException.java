package minigolf.course;

/**
 * A course file could not be read, parsed, validated or saved. The message is always one line of
 * the form {@code <file>: <field path>: <problem>} (the field path is left out when the problem
 * is not about one field), e.g. {@code courses/x.json: hole.radius: must be > 0, got -0.1}.
 */
public class CourseException extends Exception {
    private static final long serialVersionUID = 1L;
    private static final int MAX_PROBLEM_LENGTH = 400;

    private final String sourceName;
    private final String path;
    private final String problem;

    /**
     * @param sourceName the file (or other source) the course came from
     * @param path       the field path such as {@code zones[0].shape.type}, or null
     * @param problem    what is wrong, one line
     */
    public CourseException(String sourceName, String path, String problem) {
        this(sourceName, path, problem, null);
    }

    public CourseException(String sourceName, String path, String problem, Throwable cause) {
        super(format(sourceName, path, problem), cause);
        this.sourceName = sourceName;
        this.path = path;
        this.problem = problem;
    }

    /** The file or source name the error is about. */
    public String sourceName() {
        return sourceName;
    }

    /** The field path (e.g. {@code physics.gravity}), or null when the error is not about one field. */
    public String path() {
        return path;
    }

    /** The problem without the source name and field path. */
    public String problem() {
        return problem;
    }

    /** The message without the source name: {@code path: problem} or just {@code problem}. */
    public String detail() {
        return path == null ? oneLine(problem) : oneLine(path) + ": " + oneLine(problem);
    }

    private static String format(String sourceName, String path, String problem) {
        StringBuilder sb = new StringBuilder();
        sb.append(oneLine(String.valueOf(sourceName))).append(": ");
        if (path != null && !path.isEmpty()) sb.append(oneLine(path)).append(": ");
        sb.append(oneLine(problem));
        return sb.toString();
    }

    /** Control characters are escaped and very long text is cut, so a message is always one line. */
    static String oneLine(String s) {
        if (s == null) return "null";
        StringBuilder sb = new StringBuilder(Math.min(s.length(), MAX_PROBLEM_LENGTH + 16));
        for (int i = 0; i < s.length(); i++) {
            if (sb.length() >= MAX_PROBLEM_LENGTH) {
                sb.append("...");
                break;
            }
            char c = s.charAt(i);
            switch (c) {
                case '\n' -> sb.append("\\n");
                case '\r' -> sb.append("\\r");
                case '\t' -> sb.append("\\t");
                default -> {
                    if (Character.isISOControl(c) || c == '\u2028' || c == '\u2029') {
                        sb.append(String.format("\\u%04x", (int) c));
                    } else {
                        sb.append(c);
                    }
                }
            }
        }
        return sb.toString();
    }
}
