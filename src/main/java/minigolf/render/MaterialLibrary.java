package minigolf.render;

import minigolf.mesh.TriangleMesh;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The diffuse colours ({@code Kd}) of a Wavefront .mtl file by material name. Only what the renderer
 * uses is read: {@code newmtl} and {@code Kd}; every other statement (Ka, Ks, Ns, d, illum, map_*)
 * is skipped. A model is decoration as far as colours go, so a missing or broken .mtl never stops a
 * course from showing: unknown materials simply get {@link #DEFAULT_COLOR}.
 */
public final class MaterialLibrary {
    /** The colour of triangles whose material is unknown: a light stone grey. */
    public static final float[] DEFAULT_COLOR = {0.72f, 0.71f, 0.68f};

    private final Map<String, float[]> diffuse;

    private MaterialLibrary(Map<String, float[]> diffuse) {
        this.diffuse = diffuse;
    }

    public static MaterialLibrary empty() {
        return new MaterialLibrary(Map.of());
    }

    /** Reads .mtl text; lines that cannot be read are skipped. */
    public static MaterialLibrary parse(String text) {
        Map<String, float[]> colours = new HashMap<>();
        String current = null;
        for (String raw : text.split("\r\n|\n|\r")) {
            int hash = raw.indexOf('#');
            String line = (hash >= 0 ? raw.substring(0, hash) : raw).strip();
            if (line.isEmpty()) continue;
            String[] t = line.split("\\s+");
            String keyword = t[0].toLowerCase(Locale.ROOT);
            if (keyword.equals("newmtl") && t.length >= 2) {
                current = line.substring(t[0].length()).strip();
            } else if (keyword.equals("kd") && current != null && t.length >= 4) {
                try {
                    float r = clamp01(Float.parseFloat(t[1])), g = clamp01(Float.parseFloat(t[2])), b = clamp01(Float.parseFloat(t[3]));
                    colours.put(current, new float[]{r, g, b});
                } catch (NumberFormatException ignored) {
                    // a broken colour keeps the default
                }
            }
        }
        return new MaterialLibrary(colours);
    }

    /**
     * The materials of a model loaded from {@code objFile} (a path as written in the course, e.g.
     * {@code models/windmill.obj}): each {@code mtllib} of the mesh is looked up beside the .obj,
     * first under {@code courseFolder} (if not null), then among the bundled files ({@code /courses/}
     * on the classpath), confined as the course loader confines model files.
     */
    public static MaterialLibrary forModel(String objFile, TriangleMesh mesh, Path courseFolder) {
        Map<String, float[]> all = new HashMap<>();
        String normalised = objFile.replace('\\', '/');
        int slash = normalised.lastIndexOf('/');
        String dir = slash >= 0 ? normalised.substring(0, slash + 1) : "";
        for (String lib : mesh.materialLibraries()) {
            String text = read(courseFolder, dir + lib.replace('\\', '/'));
            if (text != null) all.putAll(parse(text).diffuse);
        }
        return new MaterialLibrary(all);
    }

    /** A library from the classpath, e.g. {@code /models/tree-crown.mtl}; empty if there is none. */
    public static MaterialLibrary resource(String name) {
        String text = readResource(name);
        return text == null ? empty() : parse(text);
    }

    private static String read(Path courseFolder, String relative) {
        // Confined as model files are (minigolf.io.ConfinedFiles): a course cannot make the game read other files.
        Path name;
        try {
            name = minigolf.io.ConfinedFiles.relativeName(relative);
            if (courseFolder != null) {
                Path p = minigolf.io.ConfinedFiles.resolve(courseFolder, relative);
                if (p != null) return minigolf.io.TextFiles.read(p, minigolf.course.Limits.MODEL_FILE_BYTES);
            }
        } catch (IOException e) {
            return null; // refused or unreadable: the model is drawn in its default colour
        }
        for (String resource : minigolf.io.ConfinedFiles.bundledResources(name)) {
            String text = readResource(resource);
            if (text != null) return text;
        }
        return null;
    }

    private static String readResource(String name) {
        try (InputStream in = MaterialLibrary.class.getResourceAsStream(name)) {
            return in == null ? null : new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return null;
        }
    }

    private static float clamp01(float v) {
        return Float.isFinite(v) ? Math.max(0f, Math.min(1f, v)) : 0f;
    }

    /** The diffuse colour of {@code material}, or {@link #DEFAULT_COLOR}. */
    public float[] color(String material) {
        float[] c = diffuse.get(material);
        return c != null ? c : DEFAULT_COLOR;
    }

    public boolean has(String material) {
        return diffuse.containsKey(material);
    }

    public List<String> names() {
        return List.copyOf(diffuse.keySet());
    }
}
