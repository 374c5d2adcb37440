package minigolf.course;

/**
 * The terrain height h(x, y), as the loader needs it to check that the start and the hole are on
 * dry land (h &ge; 0). The integrator supplies one per terrain, e.g. {@code terrain::height} for a
 * {@code minigolf.terrain.Terrain}, so this package does not depend on the terrain implementations.
 */
@FunctionalInterface
public interface HeightProbe {
    double height(double x, double y);
}
