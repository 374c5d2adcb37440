package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.Zone;
import minigolf.theme.Themes;
import org.junit.jupiter.api.Test;

/** Hazard zones and mud (the classic tracks' surfaces) have colours of their own; ice too. */
class HazardColoursTest {
    static float[] colour(double mu, Zone.Hazard hazard) {
        float[] rgb = new float[3];
        double stripes = TerrainMesh.unstripedColor(TerrainMesh.ColorMode.GREEN, Themes.MEADOWBROOK.materials(), mu, hazard, 1, 1, 0, 0, 1, rgb);
        assertEquals(hazard != null || mu < TerrainMesh.ICE_FRICTION || mu >= TerrainMesh.MUD_FRICTION ? 0 : 1, stripes, 1e-9);
        return rgb;
    }

    @Test
    void waterIsBlueAcidGreenIcePaleMudBrown() {
        float[] water = colour(5, new Zone.Hazard(Zone.Hazard.Kind.WATER, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.STROKE_START, 0));
        assertTrue(water[2] > water[1] && water[1] > water[0]);
        float[] shallow = colour(5, new Zone.Hazard(Zone.Hazard.Kind.WATER, Zone.Hazard.When.REST, Zone.Hazard.ReturnTo.STROKE_START, 0));
        assertTrue(shallow[2] > shallow[0] && shallow[0] > water[0]);
        float[] acid = colour(5, new Zone.Hazard(Zone.Hazard.Kind.ACID, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.COURSE_START, 0));
        assertTrue(acid[1] > acid[0] && acid[0] > acid[2]);
        float[] ice = colour(0.01, null);
        assertTrue(ice[2] > 0.6 && ice[2] > ice[0]);
        float[] mud = colour(1.2, null);
        assertTrue(mud[0] > mud[1] && mud[1] > mud[2] && mud[0] < 0.5);
        float[] grass = colour(0.1, null);
        assertTrue(grass[1] > grass[0] && grass[1] > grass[2]);
    }
}
