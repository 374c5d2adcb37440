package minigolf.editor;

/** Water in an edited grid course: the ground below zero. */
public final class CourseWater {
    private CourseWater() {
    }

    /** Whether any node in {minI, minJ, maxI, maxJ} (inclusive, as {@link ChangeSet#nodeRange()}) lies below zero. */
    public static boolean anyBelowZero(EditableCourse course, int[] range) {
        for (int j = Math.max(0, range[1]); j <= Math.min(course.rows() - 1, range[3]); j++) {
            for (int i = Math.max(0, range[0]); i <= Math.min(course.columns() - 1, range[2]); i++) {
                if (course.height(i, j) < 0) return true;
            }
        }
        return false;
    }
}
