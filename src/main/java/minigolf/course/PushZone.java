package minigolf.course;

/**
 * An area that pushes the ball (course file field {@code pushZones}), as the classic game's downhill
 * tiles: a constant force per unit mass {@code push} (m/s², in the course plane) that adds to
 * gravity's slope term while the ball rolls, and in the rule for coming to rest. Where push zones
 * overlap their pushes add.
 */
public record PushZone(Shape shape, Vec2 push) {
}
