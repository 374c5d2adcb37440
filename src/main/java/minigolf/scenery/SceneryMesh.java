package minigolf.scenery;

import minigolf.theme.Theme;

import java.util.ArrayList;
import java.util.List;

/**
 * The props of a {@link SceneryPlan} as one triangle mesh ({@link MeshWriter}'s layout) standing on
 * the ground at {@code level}, each prop one run of indices with its box, so a frame can skip the
 * props it does not see. The trees (the kind {@link Theme.Prop#TREE}) are left to the renderer's own
 * tree meshes.
 */
public final class SceneryMesh {
    /** A prop's run of indices from {@code first}, the box round it (min x, y, z, max x, y, z), and whether it stands on the skyline. */
    public record Piece(int first, int count, float[] box, boolean skyline) {
    }

    private final float[] vertices;
    private final int[] indices;
    private final List<Piece> pieces;

    private SceneryMesh(float[] vertices, int[] indices, List<Piece> pieces) {
        this.vertices = vertices;
        this.indices = indices;
        this.pieces = pieces;
    }

    public static SceneryMesh build(List<SceneryPlan.Placed> placed, Theme theme, double level) {
        return build(placed, theme, level, false);
    }

    /** As above; {@code light}: the software tier's props, the smallest parts with fewer triangles (see {@link PropMeshes#flowers}). */
    public static SceneryMesh build(List<SceneryPlan.Placed> placed, Theme theme, double level, boolean light) {
        MeshWriter w = new MeshWriter();
        List<Piece> pieces = new ArrayList<>();
        float[] rock = theme.materials().edgeColor().toArray();
        boolean snowy = theme.scenery().ground() == Theme.Ground.SNOW;
        for (SceneryPlan.Placed p : placed) {
            int start = w.indexCount(), firstVertex = w.vertexCount();
            double x = p.x(), y = p.y(), z = level;
            switch (p.prop()) {
                case TREE -> {
                    continue;
                }
                case PINE -> PropMeshes.pine(w, x, y, z, p.size(), snowy);
                case ROCK -> PropMeshes.rock(w, x, y, z, p.size(), p.seed(), rock, snowy);
                case CACTUS -> PropMeshes.cactus(w, x, y, z, p.size(), p.seed());
                case FLOWERS -> PropMeshes.flowers(w, x, y, z, p.seed(), light);
                case FENCE -> {
                    double a = Math.toRadians(p.headingDeg()), h = p.size() / 2;
                    PropMeshes.fence(w, x - Math.cos(a) * h, y - Math.sin(a) * h, x + Math.cos(a) * h, y + Math.sin(a) * h, z, snowy);
                }
                case LAMP_POST -> PropMeshes.lampPost(w, x, y, z, snowy);
                case CASTLE -> PropMeshes.castle(w, x, y, z, p.size(), p.headingDeg(), snowy);
                case MESA -> PropMeshes.mesa(w, x, y, z, p.size(), p.size() * 0.55, p.seed(), rock);
                case LIGHTHOUSE -> PropMeshes.lighthouse(w, x, y, z, rock);
                case HUT -> PropMeshes.hut(w, x, y, z, p.headingDeg(), (int) p.seed());
                case SNOWDRIFT -> PropMeshes.mound(w, x, y, z, p.size(), p.seed(), PropMeshes.SNOW, PropMeshes.SNOW);
                case DUNE -> PropMeshes.dune(w, x, y, z, p.size(), p.seed(), theme.materials().sand().toArray());
            }
            if (w.indexCount() > start) pieces.add(new Piece(start, w.indexCount() - start, w.box(firstVertex), p.skyline()));
        }
        return new SceneryMesh(w.vertices(), w.indices(), List.copyOf(pieces));
    }

    public float[] vertices() {
        return vertices;
    }

    public int[] indices() {
        return indices;
    }

    public List<Piece> pieces() {
        return pieces;
    }

    public int triangleCount() {
        return indices.length / 3;
    }
}
