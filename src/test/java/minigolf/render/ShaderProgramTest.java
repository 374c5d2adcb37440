package minigolf.render;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** Needs a GL context (a hidden window; run under xvfb-run). */
class ShaderProgramTest {
    static Window window;

    @BeforeAll
    static void open() {
        window = new Window("shader test", 64, 64, Window.Options.hidden());
    }

    @AfterAll
    static void close() {
        if (window != null) window.close();
    }

    /**
     * Issue 29's soak: a scene built again (every new hole) compiled every program afresh, and the
     * process grew by tens of kilobytes a hole under llvmpipe. Now a program is compiled once per
     * context: loading it again hands out the same one, and close() leaves it for the next scene.
     */
    @Test
    void aProgramIsCompiledOncePerContextAndOutlivesClose() {
        ShaderProgram first = ShaderProgram.load("blit");
        int kept = ShaderProgram.sharedCount();
        first.use();
        int id = org.lwjgl.opengl.GL11.glGetInteger(org.lwjgl.opengl.GL20.GL_CURRENT_PROGRAM);
        org.lwjgl.opengl.GL20.glUseProgram(0); // a deleted program in use would still count as a program
        first.close();
        assertTrue(org.lwjgl.opengl.GL20.glIsProgram(id), "close() keeps a program shared for the context");
        ShaderProgram again = ShaderProgram.load("blit");
        assertSame(first, again, "the second scene takes the program the first compiled");
        assertEquals(kept, ShaderProgram.sharedCount(), "nothing compiled the second time");
        ShaderProgram variant = ShaderProgram.load("blit", "UNUSED_IN_BLIT 1");
        assertNotSame(first, variant, "a variant with defines is a program of its own");
        assertSame(variant, ShaderProgram.load("blit", "UNUSED_IN_BLIT 1"));
        assertEquals(kept + 1, ShaderProgram.sharedCount());
    }

    static final String VERT = "layout(location = 0) in vec3 aPosition;\nvoid main() { gl_Position = vec4(aPosition, 1.0); }\n";

    @Test
    void compileErrorNamesTheShader() {
        RenderException e = assertThrows(RenderException.class,
                () -> ShaderProgram.fromSource("broken", VERT, "out vec4 c;\nvoid main() { c = vec4(undefinedThing, 1.0); }\n"));
        assertTrue(e.getMessage().contains("'broken.frag'"), e.getMessage());
        assertTrue(e.getMessage().contains("failed to compile"), e.getMessage());
        assertTrue(e.getMessage().length() > "Shader 'broken.frag' failed to compile:".length() + 5,
                "no compiler log in: " + e.getMessage());
    }

    @Test
    void vertexErrorNamesTheVertexShader() {
        RenderException e = assertThrows(RenderException.class,
                () -> ShaderProgram.fromSource("bad", "void main() { gl_Position = nonsense; }", "out vec4 c; void main() { c = vec4(1.0); }"));
        assertTrue(e.getMessage().contains("'bad.vert'"), e.getMessage());
    }

    @Test
    void linkErrorNamesTheProgram() {
        // Each stage compiles alone; the vertex shader calls a function that nothing defines.
        RenderException e = assertThrows(RenderException.class, () -> ShaderProgram.fromSource("unresolved",
                "vec4 elsewhere();\nvoid main() { gl_Position = elsewhere(); }\n",
                "out vec4 c;\nvoid main() { c = vec4(1.0); }\n"));
        assertTrue(e.getMessage().contains("'unresolved' failed to link"), e.getMessage());
    }

    @Test
    void projectShadersCompileAndLink() {
        for (String name : new String[]{"sky", "terrain", "water", "object"}) {
            try (ShaderProgram p = ShaderProgram.load(name)) {
                assertEquals(name, p.name());
                assertNotEquals(-1, p.location(name.equals("sky") ? "uInverseViewProjection" : "uViewProjection"), name);
            }
        }
    }

    @Test
    void everyShadowVariantCompiles() {
        String[][] variants = {{}, {"SHADOW_MAP", "SHADOW_TAPS 1"}, {"SHADOW_MAP", "SHADOW_TAPS 4"},
                {"SHADOW_MAP", "SHADOW_TAPS 1", "BALL_SHADOWS"}, {"SHADOW_MAP", "SHADOW_TAPS 4", "BALL_SHADOWS"}};
        for (String name : new String[]{"terrain", "terrain-vertexlit", "object", "object-vertexlit"}) {
            for (String[] defines : variants) {
                try (ShaderProgram p = ShaderProgram.load(name, defines)) {
                    assertNotEquals(-1, p.location("uViewProjection"), p.name());
                    // The shadow map's uniforms exist exactly in the shadowed variants; the balls' only with BALL_SHADOWS.
                    assertEquals(defines.length > 0, p.location("uShadowMap") != -1, p.name());
                    assertEquals(defines.length == 3, p.location("uBalls") != -1, p.name());
                }
            }
        }
        try (ShaderProgram clear = ShaderProgram.load("sky"); ShaderProgram cloudy = ShaderProgram.load("sky", "CLOUDS")) {
            assertEquals(-1, clear.location("uClouds"));
            assertNotEquals(-1, cloudy.location("uClouds"));
            assertEquals("sky+CLOUDS", cloudy.name());
        }
    }

    @Test
    void definesGoRightAfterTheVersionLine() {
        assertEquals("#version 330 core\n#define A\nvoid main(){}", ShaderProgram.withDefines("void main(){}", "#define A\n"));
        assertEquals("#version 330 core\n#define B 4\nx", ShaderProgram.withDefines("#version 330 core\nx", "#define B 4\n"));
    }

    @Test
    void missingSourceIsAClearError() {
        RenderException e = assertThrows(RenderException.class, () -> ShaderProgram.load("no-such-shader"));
        assertTrue(e.getMessage().contains("/shaders/no-such-shader.vert"), e.getMessage());
    }

    @Test
    void versionLineIsPrependedOnce() {
        assertTrue(ShaderProgram.withVersion("void main(){}").startsWith("#version 330 core\n"));
        assertEquals("#version 330 core\nx", ShaderProgram.withVersion("#version 330 core\nx"));
        assertTrue(ShaderProgram.readResource("terrain.frag").contains("vec3 shade("), "include not expanded");
    }
}
