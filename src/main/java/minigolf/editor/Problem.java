package minigolf.editor;

/** A validation problem and where on the course it is (the editor marks it there). */
public record Problem(String message, double x, double y) {
    @Override
    public String toString() {
        return message;
    }
}
