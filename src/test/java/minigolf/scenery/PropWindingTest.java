package minigolf.scenery;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import minigolf.mesh.MeshClosure;
import minigolf.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * Every prop is wound counter-clockwise seen from outside: its normals are made from the winding and the
 * software tier skips the faces turned away from the camera, so a face wound inwards is lit as if from
 * inside and vanishes where it should show (the beach huts' roofs were wound inside out). Checked per
 * prop: neighbouring faces wound alike (MeshClosure.woundAlike; not for props of parts that touch) and a
 * positive signed volume (outwards, standing on z = 0, where an open foot adds nothing).
 */
class PropWindingTest {
    private static final float[] C = {0.5f, 0.5f, 0.5f};

    @Test
    void everyPropIsWoundOutwards() {
        Map<String, Consumer<MeshWriter>> props = new LinkedHashMap<>();
        props.put("hut", w -> PropMeshes.hut(w, 0, 0, 0, 30, 1));
        props.put("castle", w -> PropMeshes.castle(w, 0, 0, 0, 6, 20, true));
        props.put("lighthouse", w -> PropMeshes.lighthouse(w, 0, 0, 0, C));
        props.put("rock", w -> PropMeshes.rock(w, 0, 0, 0, 0.6, 7, C, true));
        props.put("pine", w -> PropMeshes.pine(w, 0, 0, 0, 3, true));
        props.put("cactus", w -> PropMeshes.cactus(w, 0, 0, 0, 2, 5));
        props.put("flowers", w -> PropMeshes.flowers(w, 0, 0, 0, 3));
        props.put("fence", w -> PropMeshes.fence(w, 0, 0, 3, 1, 0, true));
        props.put("lamp post", w -> PropMeshes.lampPost(w, 0, 0, 0, true));
        props.put("mesa", w -> PropMeshes.mesa(w, 0, 0, 0, 8, 5, 3, C));
        props.put("mound", w -> PropMeshes.mound(w, 0, 0, 0, 2, 4, C, C));
        props.put("dune", w -> PropMeshes.dune(w, 0, 0, 0, 2, 4, C));
        List<String> wrong = new ArrayList<>();
        for (var e : props.entrySet()) {
            MeshWriter w = new MeshWriter();
            e.getValue().accept(w);
            float[] v = w.vertices();
            int n = w.vertexCount();
            float[] positions = new float[3 * n];
            for (int i = 0; i < n; i++) System.arraycopy(v, MeshWriter.STRIDE * i, positions, 3 * i, 3);
            int[] idx = w.indices();
            assertTrue(idx.length > 0, e.getKey());
            TriangleMesh mesh = new TriangleMesh(positions, new float[3 * n], new float[2 * n], idx, List.of(), List.of());
            double volume = 0;
            for (int t = 0; t < idx.length; t += 3) {
                float[] a = corner(positions, idx[t]), b = corner(positions, idx[t + 1]), c = corner(positions, idx[t + 2]);
                volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
            }
            // The castle and the lighthouse stack parts that touch along edges (one edge, two parts, same direction).
            boolean stacked = e.getKey().equals("castle") || e.getKey().equals("lighthouse");
            if (!(stacked || MeshClosure.woundAlike(mesh)) || volume <= 0) {
                wrong.add(e.getKey() + " (wound alike " + MeshClosure.woundAlike(mesh) + ", volume " + volume + ")");
            }
        }
        assertEquals(List.of(), wrong);
    }

    private static float[] corner(float[] p, int i) {
        return new float[]{p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    }
}
