package minigolf.render;

import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3f;

/**
 * The software tier lights obstacles per vertex (object-vertexlit): a flat triangle whose normal faces
 * away from the sun (n.l <= 0) gets no diffuse and no specular light at any vertex, so its shadow tap
 * could only multiply zero and it can be drawn without one. This reorders a mesh's pieces into the
 * triangles the sun may light and those it cannot: all pieces' lit parts first, then all their backlit
 * parts, both in piece order with the piece's box, so that neighbouring pieces still draw as one run.
 * Stay in the lit part: open pieces (drawn with both faces, the shader turns their normals to the eye),
 * triangles with smooth normals (a normal turned to the eye at a silhouette may face the sun) and the
 * flag's cloth (its normals move with the wind). Plain arithmetic, no GL.
 */
final class BacklitSplit {
    /** The reordered indices and the pieces' two parts (empty parts left out). */
    record Result(int[] indices, List<ObstacleMeshes.Piece> lit, List<ObstacleMeshes.Piece> backlit) {
    }

    /** wind.glsl moves vertices whose material id (the colour's 4th component) is above this: the cloth. */
    static final float CLOTH_FROM = 5.5f;

    private BacklitSplit() {
    }

    static Result split(MeshData mesh, List<ObstacleMeshes.Piece> pieces, Vector3f toSun) {
        int[] in = mesh.indices();
        if (pieces.stream().mapToInt(ObstacleMeshes.Piece::count).sum() != in.length) {
            throw new IllegalArgumentException("the pieces do not cover the mesh's " + in.length + " indices");
        }
        int[] out = new int[in.length];
        boolean[] back = new boolean[in.length / 3];
        int backCount = 0;
        for (ObstacleMeshes.Piece p : pieces) {
            if (p.open()) continue;
            for (int t = p.first() / 3; t < (p.first() + p.count()) / 3; t++) {
                back[t] = backlit(mesh, in[3 * t], in[3 * t + 1], in[3 * t + 2], toSun);
                if (back[t]) backCount += 3;
            }
        }
        List<ObstacleMeshes.Piece> lit = new ArrayList<>(), backlit = new ArrayList<>();
        int litAt = 0, backAt = in.length - backCount;
        for (ObstacleMeshes.Piece p : pieces) {
            int litFirst = litAt, backFirst = backAt;
            for (int t = p.first() / 3; t < (p.first() + p.count()) / 3; t++) {
                int at = back[t] ? backAt : litAt;
                System.arraycopy(in, 3 * t, out, at, 3);
                if (back[t]) backAt += 3;
                else litAt += 3;
            }
            if (litAt > litFirst) lit.add(new ObstacleMeshes.Piece(litFirst, litAt - litFirst, p.box(), p.open()));
            if (backAt > backFirst) backlit.add(new ObstacleMeshes.Piece(backFirst, backAt - backFirst, p.box(), p.open()));
        }
        return new Result(out, List.copyOf(lit), List.copyOf(backlit));
    }

    /** A flat triangle (one normal at its three vertices), not cloth, whose normal meets the sun at 90 degrees or more. */
    static boolean backlit(MeshData mesh, int a, int b, int c, Vector3f toSun) {
        int stride = mesh.stride();
        float[] v = mesh.vertices();
        int na = a * stride + 3, nb = b * stride + 3, nc = c * stride + 3;
        for (int k = 0; k < 3; k++) {
            if (v[na + k] != v[nb + k] || v[na + k] != v[nc + k]) return false;
        }
        if (stride >= 10 && Math.max(v[a * stride + 9], Math.max(v[b * stride + 9], v[c * stride + 9])) > CLOTH_FROM) return false;
        return v[na] * toSun.x + v[na + 1] * toSun.y + v[na + 2] * toSun.z <= 0;
    }
}
