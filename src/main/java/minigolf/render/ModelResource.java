package minigolf.render;

import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

/**
 * A Wavefront model the game ships, {@code /models/NAME.obj} with the materials its {@code mtllib}
 * names beside it ({@code /models/NAME.mtl} if it names none) on the classpath (the tree crown and
 * its lighter twin, which shares the crown's materials; the flag), parsed once and shared.
 */
record ModelResource(TriangleMesh mesh, MaterialLibrary materials) {
    private static final Map<String, ModelResource> LOADED = new HashMap<>();

    static synchronized ModelResource get(String name) {
        ModelResource m = LOADED.get(name);
        if (m != null) return m;
        String obj = "/models/" + name + ".obj";
        try (InputStream in = ModelResource.class.getResourceAsStream(obj)) {
            if (in == null) throw new RenderException("missing resource " + obj, null);
            TriangleMesh mesh = ObjParser.parse(in);
            String library = mesh.materialLibraries().isEmpty() || mesh.materialLibraries().get(0).contains("/")
                    ? name + ".mtl" : mesh.materialLibraries().get(0);
            m = new ModelResource(mesh, MaterialLibrary.resource("/models/" + library));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (ObjException e) {
            throw new RenderException(obj + ": " + e.getMessage(), e);
        }
        LOADED.put(name, m);
        return m;
    }

    /** The model turned by {@code rotationDeg} about z, scaled, and moved to (x, y, z), coloured by its materials. */
    MeshData placed(double x, double y, double z, double rotationDeg, double scale) {
        return ObstacleMeshes.placedModel(mesh, materials, x, y, z, rotationDeg, scale);
    }
}
