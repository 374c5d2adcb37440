package minigolf.theme;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static minigolf.theme.Theme.Prop.*;

/**
 * The bundled worlds, by id (a course file's {@code world} field): Meadowbrook, the original park
 * (the default for a course that names none), and three themed worlds with 18 holes each
 * (courses/rounds): Gull Bay, a seaside links; Red Rock Canyon, a desert canyon at the end of the
 * afternoon; Frostkeep, a castle garden in winter.
 */
public final class Themes {
    public static final String DEFAULT_ID = "meadowbrook";

    public static final Theme MEADOWBROOK = new Theme(DEFAULT_ID, "Meadowbrook",
            "A park on a summer afternoon: mown greens on a grassy plinth, wooden rails, trees all round.",
            new Theme.Light(230.7, 44.6, Rgb.of(1.0, 0.96, 0.88), Rgb.of(0.40, 0.46, 0.56), Rgb.of(0.24, 0.22, 0.16), 1.0),
            new Theme.Sky(Rgb.of(0.22, 0.45, 0.82), Rgb.of(0.80, 0.88, 0.96), Rgb.of(0.55, 0.70, 0.88),
                    Rgb.of(0.78, 0.87, 0.96), 0.004, 0.45, Rgb.of(1.0, 0.99, 0.96), Rgb.of(0.80, 0.83, 0.88),
                    Rgb.of(1.0, 0.95, 0.80)),
            new Theme.Materials(Rgb.of(0.13, 0.38, 0.11), Rgb.of(0.50, 0.76, 0.28), 0.92, Rgb.of(0.87, 0.78, 0.53),
                    Rgb.of(0.42, 0.37, 0.24), Theme.RailMaterial.WOOD, Rgb.of(0.60, 0.47, 0.32), Rgb.of(0.68, 0.40, 0.30),
                    Theme.EdgeMaterial.SOIL, Rgb.of(0.45, 0.33, 0.20), Rgb.of(0.29, 0.45, 0.18), Rgb.of(0.10, 0.32, 0.42)),
            new Theme.Scenery(Theme.Ground.GRASS, false, 0, List.of(new Theme.PropCount(TREE, 48), new Theme.PropCount(FLOWERS, 16),
                    new Theme.PropCount(ROCK, 6), new Theme.PropCount(FENCE, 4))),
            Theme.Ambience.BIRDS);

    public static final Theme SEASIDE = new Theme("seaside", "Gull Bay",
            "A seaside links on a bright morning: white-railed greens on a grassy headland, dunes, beach huts,"
                    + " a lighthouse and the sea all round.",
            new Theme.Light(205, 52, Rgb.of(1.05, 1.0, 0.92), Rgb.of(0.40, 0.48, 0.60), Rgb.of(0.30, 0.30, 0.24), 1.0),
            new Theme.Sky(Rgb.of(0.14, 0.40, 0.80), Rgb.of(0.80, 0.89, 0.97), Rgb.of(0.60, 0.75, 0.90),
                    Rgb.of(0.80, 0.88, 0.96), 0.003, 0.35, Rgb.of(1.0, 1.0, 0.98), Rgb.of(0.78, 0.82, 0.90),
                    Rgb.of(1.0, 0.97, 0.85)),
            new Theme.Materials(Rgb.of(0.15, 0.42, 0.14), Rgb.of(0.40, 0.68, 0.27), 0.90, Rgb.of(0.93, 0.86, 0.66),
                    Rgb.of(0.52, 0.48, 0.36), Theme.RailMaterial.PAINTED_WOOD, Rgb.of(0.93, 0.93, 0.90),
                    Rgb.of(0.22, 0.44, 0.70), Theme.EdgeMaterial.ROCK, Rgb.of(0.56, 0.54, 0.50),
                    Rgb.of(0.52, 0.60, 0.33), Rgb.of(0.06, 0.34, 0.46)),
            new Theme.Scenery(Theme.Ground.GRASS, true, 14, List.of(new Theme.PropCount(LIGHTHOUSE, 1), new Theme.PropCount(HUT, 6),
                    new Theme.PropCount(DUNE, 12), new Theme.PropCount(ROCK, 16), new Theme.PropCount(FENCE, 8),
                    new Theme.PropCount(FLOWERS, 24), new Theme.PropCount(LAMP_POST, 4))),
            Theme.Ambience.WAVES);

    public static final Theme CANYON = new Theme("canyon", "Red Rock Canyon",
            "A desert canyon late in the afternoon: greens on sandstone ledges with stone rails, red sand traps,"
                    + " cacti, and buttes glowing on the skyline.",
            new Theme.Light(150, 24, Rgb.of(1.18, 0.90, 0.64), Rgb.of(0.40, 0.42, 0.50), Rgb.of(0.42, 0.28, 0.18), 1.6),
            new Theme.Sky(Rgb.of(0.24, 0.44, 0.76), Rgb.of(0.96, 0.80, 0.62), Rgb.of(0.82, 0.62, 0.46),
                    Rgb.of(0.93, 0.78, 0.60), 0.005, 0.18, Rgb.of(1.0, 0.90, 0.78), Rgb.of(0.80, 0.66, 0.60),
                    Rgb.of(1.0, 0.78, 0.52)),
            new Theme.Materials(Rgb.of(0.20, 0.40, 0.15), Rgb.of(0.50, 0.68, 0.26), 0.91, Rgb.of(0.86, 0.56, 0.34),
                    Rgb.of(0.46, 0.32, 0.22), Theme.RailMaterial.SANDSTONE, Rgb.of(0.80, 0.52, 0.34),
                    Rgb.of(0.62, 0.36, 0.22), Theme.EdgeMaterial.SANDSTONE, Rgb.of(0.74, 0.44, 0.27),
                    Rgb.of(0.80, 0.55, 0.35), Rgb.of(0.10, 0.36, 0.40)),
            new Theme.Scenery(Theme.Ground.SAND, false, 0, List.of(new Theme.PropCount(MESA, 9), new Theme.PropCount(CACTUS, 26),
                    new Theme.PropCount(ROCK, 22), new Theme.PropCount(FENCE, 3))),
            Theme.Ambience.DESERT_WIND);

    public static final Theme WINTER = new Theme("winter", "Frostkeep",
            "A castle garden in winter: frosted greens behind grey stone rails, snow traps and ice, lamp posts,"
                    + " snowy pines and the castle's walls and towers.",
            new Theme.Light(250, 21, Rgb.of(1.0, 0.94, 0.84), Rgb.of(0.50, 0.56, 0.68), Rgb.of(0.46, 0.48, 0.54), 2.0),
            new Theme.Sky(Rgb.of(0.36, 0.50, 0.72), Rgb.of(0.86, 0.89, 0.94), Rgb.of(0.80, 0.84, 0.90),
                    Rgb.of(0.86, 0.89, 0.94), 0.008, 0.6, Rgb.of(0.98, 0.98, 1.0), Rgb.of(0.72, 0.75, 0.82),
                    Rgb.of(1.0, 0.92, 0.80)),
            new Theme.Materials(Rgb.of(0.17, 0.36, 0.24), Rgb.of(0.44, 0.62, 0.44), 0.93, Rgb.of(0.93, 0.95, 0.98),
                    Rgb.of(0.36, 0.38, 0.40), Theme.RailMaterial.STONE, Rgb.of(0.64, 0.64, 0.66),
                    Rgb.of(0.52, 0.52, 0.56), Theme.EdgeMaterial.STONE_WALL, Rgb.of(0.52, 0.52, 0.55),
                    Rgb.of(0.90, 0.93, 0.97), Rgb.of(0.12, 0.26, 0.36)),
            new Theme.Scenery(Theme.Ground.SNOW, false, 0, List.of(new Theme.PropCount(CASTLE, 1), new Theme.PropCount(PINE, 34),
                    new Theme.PropCount(LAMP_POST, 8), new Theme.PropCount(SNOWDRIFT, 14), new Theme.PropCount(ROCK, 6),
                    new Theme.PropCount(FENCE, 4))),
            Theme.Ambience.WINTER_WIND);

    private static final Map<String, Theme> BY_ID = new LinkedHashMap<>();

    static {
        for (Theme t : List.of(MEADOWBROOK, SEASIDE, CANYON, WINTER)) BY_ID.put(t.id(), t);
    }

    private Themes() {
    }

    /** Every bundled world, Meadowbrook first. */
    public static List<Theme> all() {
        return List.copyOf(BY_ID.values());
    }

    /** The ids a course file may name, in order. */
    public static List<String> ids() {
        return List.copyOf(BY_ID.keySet());
    }

    /** The world with this id, or null. */
    public static Theme byId(String id) {
        return BY_ID.get(id);
    }

    /** The world with this id, or Meadowbrook for null. */
    public static Theme of(String id) {
        if (id == null) return MEADOWBROOK;
        Theme t = BY_ID.get(id);
        if (t == null) throw new IllegalArgumentException("no world '" + id + "' (known: " + String.join(", ", ids()) + ")");
        return t;
    }
}
