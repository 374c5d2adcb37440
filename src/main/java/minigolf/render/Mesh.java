package minigolf.render;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;

import static org.lwjgl.opengl.GL15.*;
import static org.lwjgl.opengl.GL20.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30.*;
import static org.lwjgl.system.MemoryUtil.*;

/** A vertex array with its vertex and index buffers on the GPU; drawn as triangles. */
public final class Mesh implements AutoCloseable {
    private final int vao;
    private final int vbo;
    private final int ebo;
    private final int indexCount;
    private boolean closed;

    public Mesh(MeshData data) {
        indexCount = data.indices().length;
        vao = glGenVertexArrays();
        glBindVertexArray(vao);
        vbo = glGenBuffers();
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        FloatBuffer vertices = memAllocFloat(data.vertices().length);
        try {
            vertices.put(data.vertices()).flip();
            glBufferData(GL_ARRAY_BUFFER, vertices, GL_STATIC_DRAW);
        } finally {
            memFree(vertices);
        }
        ebo = glGenBuffers();
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
        IntBuffer indices = memAllocInt(indexCount);
        try {
            indices.put(data.indices()).flip();
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, indices, GL_STATIC_DRAW);
        } finally {
            memFree(indices);
        }
        int strideBytes = data.stride() * Float.BYTES;
        long offset = 0;
        int[] layout = data.layout();
        for (int location = 0; location < layout.length; location++) {
            glEnableVertexAttribArray(location);
            glVertexAttribPointer(location, layout[location], GL_FLOAT, false, strideBytes, offset);
            offset += (long) layout[location] * Float.BYTES;
        }
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    /**
     * Overwrites part of the vertex buffer in place (glBufferSubData): {@code vertices} go to the
     * buffer from float {@code firstFloat} on. For live edits that keep the vertex count.
     */
    public void updateVertices(int firstFloat, float[] vertices) {
        FloatBuffer buffer = memAllocFloat(vertices.length);
        try {
            buffer.put(vertices).flip();
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferSubData(GL_ARRAY_BUFFER, (long) firstFloat * Float.BYTES, buffer);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        } finally {
            memFree(buffer);
        }
    }

    /** Overwrites part of the index buffer in place: {@code indices} go to the buffer from index {@code firstIndex} on. */
    public void updateIndices(int firstIndex, int[] indices) {
        IntBuffer buffer = memAllocInt(indices.length);
        try {
            buffer.put(indices).flip();
            glBindVertexArray(vao);
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, (long) firstIndex * Integer.BYTES, buffer);
            glBindVertexArray(0);
        } finally {
            memFree(buffer);
        }
    }

    public int indexCount() {
        return indexCount;
    }

    public void draw() {
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0L);
        glBindVertexArray(0);
    }

    /** Draws {@code count} indices from index {@code first}. */
    public void drawRange(int first, int count) {
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, (long) first * Integer.BYTES);
        glBindVertexArray(0);
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        glDeleteBuffers(ebo);
    }
}
