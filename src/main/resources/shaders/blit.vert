// A quad over the whole viewport from gl_VertexID (no vertex buffer; draw 4 vertices as a strip).
out vec2 vUv;

void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 1), float(gl_VertexID & 2)); // (0,0) (2,0) (0,2) (2,2)
    vUv = p * 0.5;
    gl_Position = vec4(p - 1.0, 0.0, 1.0);
}
