package minigolf.terrain;

import minigolf.course.TerrainSpec;

/** Builds the terrain a course file describes. */
public final class Terrains {
    private Terrains() {
    }

    /** @throws minigolf.expr.ExpressionException for a height expression that does not parse */
    public static Terrain create(TerrainSpec spec) {
        if (spec instanceof TerrainSpec.HeightExpression e) {
            return new ExpressionTerrain(e.source());
        }
        return new GridTerrain((TerrainSpec.HeightGrid) spec);
    }
}
