package minigolf.theme;

import java.util.List;

/**
 * A themed world a course is set in: its light and sky, the materials of its ground, rails and
 * edges, what stands round the course, and its ambient sound. Plain data (no OpenGL): the renderer
 * and the sound read it. Courses name their world by {@link #id} (the course file's {@code world}
 * field); {@link Themes} holds the bundled ones.
 */
public record Theme(String id, String title, String description, Light light, Sky sky, Materials materials,
                    Scenery scenery, Ambience ambience) {

    /**
     * The sun and the ambient light. The sun stands at {@code azimuthDeg} (counter-clockwise from
     * +x, seen from above) and {@code elevationDeg} above the horizon. {@code shadowSoftness} widens
     * the shadow filter (1: the default 3x3-texel footprint; 2: twice as wide, a hazier sun).
     */
    public record Light(double azimuthDeg, double elevationDeg, Rgb sun, Rgb skyAmbient, Rgb groundAmbient,
                        double shadowSoftness) {
        /** The unit vector from the ground towards the sun (x, y, z). */
        public double[] direction() {
            double a = Math.toRadians(azimuthDeg), e = Math.toRadians(elevationDeg);
            return new double[]{Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)};
        }
    }

    /**
     * The sky dome and the air: gradient colours (zenith, horizon, and the haze below the horizon),
     * the fog that far things fade into ({@code fogDensity} per metre), the clouds' cover (0 clear,
     * 1 overcast) and colours, and the sun's glow.
     */
    public record Sky(Rgb zenith, Rgb horizon, Rgb below, Rgb fog, double fogDensity, double cloudCover,
                      Rgb cloudLit, Rgb cloudShade, Rgb sunGlow) {
    }

    /** What a rail (a course wall) is made of: its texture and how its top is shaped. */
    public enum RailMaterial {
        /** Planks with grain, rounded top. */
        WOOD,
        /** Painted boards: wood grain under white paint. */
        PAINTED_WOOD,
        /** Dressed stone blocks with mortar joints, rounded coping. */
        STONE,
        /** Red sandstone blocks. */
        SANDSTONE
    }

    /** What the course's edges (the plinth it stands on) are made of. */
    public enum EdgeMaterial {
        SOIL, ROCK, SANDSTONE, SNOWY_ROCK, STONE_WALL
    }

    /**
     * The course's materials: the grass from low to high ground (mown stripes {@code stripeShade} as
     * bright), sand, the lake bed, the rails, boxes and the course's edge (the plinth's sides) and the
     * ground round the course.
     */
    public record Materials(Rgb grassLow, Rgb grassHigh, double stripeShade, Rgb sand, Rgb lakeBed,
                            RailMaterial rail, Rgb railColor, Rgb boxColor, EdgeMaterial edge, Rgb edgeColor,
                            Rgb surroundGround, Rgb water) {
    }

    /** Kinds of props that stand round a course. */
    public enum Prop {
        /** Broad-leaved trees (the course's own tree model). */
        TREE,
        /** Conifers, snow on their tiers in a winter world. */
        PINE,
        ROCK,
        /** Saguaro cacti. */
        CACTUS,
        /** Clumps of flowers in the grass. */
        FLOWERS,
        /** Post-and-rail fence lengths. */
        FENCE,
        LAMP_POST,
        /** Crenellated castle walls with towers, on the skyline. */
        CASTLE,
        /** Flat-topped buttes of layered rock, on the skyline. */
        MESA,
        /** A striped lighthouse. */
        LIGHTHOUSE,
        /** Beach huts. */
        HUT,
        /** Snow drifts (low mounds). */
        SNOWDRIFT,
        /** Dunes / grassy dune mounds. */
        DUNE
    }

    /** How many of one prop kind stand round the course (at high quality; software quality takes about half). */
    public record PropCount(Prop prop, int count) {
    }

    /** What the ground round the course is covered with (its texture; snow also lies on props). */
    public enum Ground {
        GRASS, SAND, SNOW
    }

    /**
     * The ground round the course and what stands on it. With {@code sea} the ground ends at a
     * shore {@code shoreDistance} metres from the course and water reaches to the horizon.
     */
    public record Scenery(Ground ground, boolean sea, double shoreDistance, List<PropCount> props) {
        public Scenery {
            props = List.copyOf(props);
        }
    }

    /** The world's quiet background sound, synthesised in code (see minigolf.app.AmbientSynth). */
    public enum Ambience {
        NONE, BIRDS, WAVES, DESERT_WIND, WINTER_WIND
    }
}
