package minigolf.render;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.lwjgl.system.MemoryStack;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.lwjgl.opengl.GL20.*;

/**
 * A linked vertex + fragment program. Sources come from the classpath ({@code /shaders/NAME.vert} and
 * {@code /shaders/NAME.frag}) without a {@code #version} line: {@code #version 330 core} is prepended
 * here, as LWJGL's demos do, so one place decides the GLSL version. A line
 * {@code #include "file.glsl"} is replaced by {@code /shaders/file.glsl} (shared lighting code).
 *
 * <p>The programs of {@link #load} are compiled once per GL context and kept for its life: a scene
 * built again (every new hole, a preview, the editor's rebuilt terrain) takes the same programs, and
 * their {@link #close()} keeps them. Compiling afresh each hole made a software driver (llvmpipe)
 * translate every shader again, and the process's memory grew by tens of kilobytes a hole (issue 29's
 * soak). Passes set every uniform they use before each draw, so sharing a program is safe.
 */
public final class ShaderProgram implements AutoCloseable {
    public static final String VERSION_LINE = "#version 330 core\n";
    private static final Pattern INCLUDE = Pattern.compile("(?m)^\\s*#include\\s+\"([^\"]+)\"\\s*$");

    /** The context's programs by label (a context's GLCapabilities is its identity; it dies with the context). */
    private static final Map<org.lwjgl.opengl.GLCapabilities, Map<String, ShaderProgram>> SHARED = new java.util.WeakHashMap<>();

    private final String name;
    private final int program;
    private final Map<String, Integer> locations = new HashMap<>();
    /** Kept for the context's life ({@link #load}): close() leaves it. */
    private boolean shared;

    private ShaderProgram(String name, int program) {
        this.name = name;
        this.program = program;
    }

    /** Loads, compiles and links {@code /shaders/NAME.vert} and {@code /shaders/NAME.frag}, once per context. */
    public static ShaderProgram load(String name) {
        return shared(name, () -> fromSource(name, readResource(name + ".vert"), readResource(name + ".frag")));
    }

    /** The current context's program {@code label}, made by {@code make} the first time. */
    private static ShaderProgram shared(String label, java.util.function.Supplier<ShaderProgram> make) {
        org.lwjgl.opengl.GLCapabilities context = org.lwjgl.opengl.GL.getCapabilities();
        synchronized (SHARED) {
            Map<String, ShaderProgram> programs = SHARED.computeIfAbsent(context, c -> new HashMap<>());
            ShaderProgram p = programs.get(label);
            if (p == null) {
                p = make.get();
                p.shared = true;
                programs.put(label, p);
            }
            return p;
        }
    }

    /** Programs kept for the current context (tests: a scene built twice compiles nothing the second time). */
    static int sharedCount() {
        synchronized (SHARED) {
            Map<String, ShaderProgram> programs = SHARED.get(org.lwjgl.opengl.GL.getCapabilities());
            return programs == null ? 0 : programs.size();
        }
    }

    /**
     * As {@link #load(String)}, with {@code #define} lines after the version line in both stages, e.g.
     * {@code "SHADOW_MAP"} or {@code "SHADOW_TAPS 4"}. Variants are compiled instead of branching on
     * uniforms because software rasterisers (llvmpipe) run both sides of every branch for each pixel.
     */
    public static ShaderProgram load(String name, String... defines) {
        if (defines.length == 0) return load(name);
        StringBuilder d = new StringBuilder();
        for (String define : defines) d.append("#define ").append(define).append('\n');
        String label = name + String.join("", java.util.Arrays.stream(defines).map(x -> "+" + x.split(" ")[0]).toList());
        return shared(name + "\n" + d, () -> fromSource(label, withDefines(readResource(name + ".vert"), d.toString()),
                withDefines(readResource(name + ".frag"), d.toString())));
    }

    /** The source with its version line first and the defines right after it. */
    static String withDefines(String source, String defines) {
        String versioned = withVersion(source);
        int eol = versioned.indexOf('\n');
        return versioned.substring(0, eol + 1) + defines + versioned.substring(eol + 1);
    }

    /** Compiles and links the given sources; errors name {@code NAME.vert} / {@code NAME.frag}. */
    public static ShaderProgram fromSource(String name, String vertexSource, String fragmentSource) {
        int vs = compile(name + ".vert", GL_VERTEX_SHADER, vertexSource);
        int fs;
        try {
            fs = compile(name + ".frag", GL_FRAGMENT_SHADER, fragmentSource);
        } catch (RuntimeException e) {
            glDeleteShader(vs);
            throw e;
        }
        int program = glCreateProgram();
        glAttachShader(program, vs);
        glAttachShader(program, fs);
        glLinkProgram(program);
        glDetachShader(program, vs);
        glDetachShader(program, fs);
        glDeleteShader(vs);
        glDeleteShader(fs);
        if (glGetProgrami(program, GL_LINK_STATUS) != GL_TRUE) {
            String log = glGetProgramInfoLog(program);
            glDeleteProgram(program);
            throw new RenderException("Shader program '" + name + "' failed to link:\n" + log.strip());
        }
        return new ShaderProgram(name, program);
    }

    private static int compile(String shaderName, int type, String source) {
        int shader = glCreateShader(type);
        glShaderSource(shader, withVersion(source));
        glCompileShader(shader);
        if (glGetShaderi(shader, GL_COMPILE_STATUS) != GL_TRUE) {
            String log = glGetShaderInfoLog(shader);
            glDeleteShader(shader);
            throw new RenderException("Shader '" + shaderName + "' failed to compile:\n" + log.strip());
        }
        return shader;
    }

    static String withVersion(String source) {
        return source.stripLeading().startsWith("#version") ? source : VERSION_LINE + source;
    }

    /** The text of {@code /shaders/FILE} with its {@code #include}s expanded. */
    public static String readResource(String file) {
        return expandIncludes(file, new HashSet<>());
    }

    private static String expandIncludes(String file, Set<String> seen) {
        if (!seen.add(file)) throw new RenderException("Shader include cycle at '" + file + "'");
        String text;
        try (InputStream in = ShaderProgram.class.getResourceAsStream("/shaders/" + file)) {
            if (in == null) throw new RenderException("Shader source '/shaders/" + file + "' is not on the classpath");
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new RenderException("Could not read shader source '/shaders/" + file + "'", e);
        }
        Matcher m = INCLUDE.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(out, Matcher.quoteReplacement(expandIncludes(m.group(1), seen)));
        }
        m.appendTail(out);
        seen.remove(file);
        return out.toString();
    }

    public String name() {
        return name;
    }

    public void use() {
        glUseProgram(program);
    }

    /** The uniform's location, or -1 when the linker dropped it (setting -1 is a no-op in GL). */
    public int location(String uniform) {
        return locations.computeIfAbsent(uniform, u -> glGetUniformLocation(program, u));
    }

    public void set(String uniform, Matrix4f m) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            glUniformMatrix4fv(location(uniform), false, m.get(stack.mallocFloat(16)));
        }
    }

    public void set(String uniform, Matrix3f m) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            glUniformMatrix3fv(location(uniform), false, m.get(stack.mallocFloat(9)));
        }
    }

    public void set(String uniform, Vector3f v) {
        glUniform3f(location(uniform), v.x, v.y, v.z);
    }

    public void set(String uniform, Vector4f v) {
        glUniform4f(location(uniform), v.x, v.y, v.z, v.w);
    }

    public void set(String uniform, float x, float y) {
        glUniform2f(location(uniform), x, y);
    }

    public void set(String uniform, float x, float y, float z) {
        glUniform3f(location(uniform), x, y, z);
    }

    public void set(String uniform, float x, float y, float z, float w) {
        glUniform4f(location(uniform), x, y, z, w);
    }

    public void set(String uniform, float v) {
        glUniform1f(location(uniform), v);
    }

    /** A vec4[] uniform: the first {@code count} vectors (4 floats each) of {@code xyzw}. */
    public void setVec4Array(String uniform, float[] xyzw, int count) {
        if (count <= 0) return;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            glUniform4fv(location(uniform), stack.floats(java.util.Arrays.copyOf(xyzw, 4 * count)));
        }
    }

    public void set(String uniform, int v) {
        glUniform1i(location(uniform), v);
    }

    /** Deletes the program, unless it is one of the context's kept programs ({@link #load}). */
    @Override
    public void close() {
        if (!shared) glDeleteProgram(program);
    }
}
