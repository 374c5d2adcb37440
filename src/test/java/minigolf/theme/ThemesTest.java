package minigolf.theme;

import static org.junit.jupiter.api.Assertions.*;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The bundled worlds: Meadowbrook by default, three themed ones, each its own place. */
class ThemesTest {
    @Test
    void meadowbrookIsTheDefaultAndThereAreThreeThemedWorlds() {
        assertEquals(List.of("meadowbrook", "seaside", "canyon", "winter"), Themes.ids());
        assertSame(Themes.MEADOWBROOK, Themes.of(null));
        assertSame(Themes.CANYON, Themes.of("canyon"));
        assertNull(Themes.byId("moon"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Themes.of("moon"));
        assertEquals("no world 'moon' (known: meadowbrook, seaside, canyon, winter)", e.getMessage());
    }

    @Test
    void everyWorldHasItsOwnTitleLightSkyAndGround() {
        Set<String> titles = new HashSet<>();
        Set<Theme.RailMaterial> rails = new HashSet<>();
        Set<Theme.Ambience> sounds = new HashSet<>();
        for (Theme t : Themes.all()) {
            assertTrue(titles.add(t.title()), t.title());
            rails.add(t.materials().rail());
            sounds.add(t.ambience());
            double[] d = t.light().direction();
            assertEquals(1, Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 1e-12, t.id());
            assertTrue(d[2] > 0.3, t.id() + ": the sun is above the horizon");
            assertTrue(t.sky().fogDensity() > 0 && t.sky().cloudCover() >= 0 && t.sky().cloudCover() <= 1, t.id());
            assertFalse(t.scenery().props().isEmpty(), t.id() + " has props");
            assertFalse(t.description().isBlank(), t.id());
        }
        assertEquals(4, rails.size(), "wood, painted wood, sandstone and stone rails");
        assertEquals(4, sounds.size(), "each world sounds different");
        assertTrue(Themes.SEASIDE.scenery().sea() && !Themes.CANYON.scenery().sea(), "only the seaside has the sea");
        assertEquals(Theme.Ground.SNOW, Themes.WINTER.scenery().ground());
        assertEquals(Theme.Ground.SAND, Themes.CANYON.scenery().ground());
        // The canyon's low sun: long shadows, softer edges.
        assertTrue(Themes.CANYON.light().elevationDeg() < Themes.MEADOWBROOK.light().elevationDeg());
        assertTrue(Themes.CANYON.light().shadowSoftness() > Themes.MEADOWBROOK.light().shadowSoftness());
    }

    @Test
    void meadowbrooksSunIsTheAfternoonSunOfBefore() {
        double[] d = Themes.MEADOWBROOK.light().direction();
        double l = Math.sqrt(0.45 * 0.45 + 0.55 * 0.55 + 0.70 * 0.70);
        assertArrayEquals(new double[]{-0.45 / l, -0.55 / l, 0.70 / l}, d, 2e-3);
    }

    @Test
    void rgbHexAndMix() {
        assertEquals(Rgb.of(1, 0.5019607843137255, 0), Rgb.hex(0xFF8000));
        assertEquals(Rgb.of(0.5, 0.5, 0.5), Rgb.of(0, 0, 0).mix(Rgb.of(1, 1, 1), 0.5));
        assertArrayEquals(new float[]{0.2f, 0.4f, 0.6f}, Rgb.of(0.1, 0.2, 0.3).times(2).toArray(), 1e-6f);
    }
}
