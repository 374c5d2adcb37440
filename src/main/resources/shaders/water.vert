layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aDepth;

uniform mat4 uViewProjection;

out vec3 vWorld;
out float vDepth;
out vec4 vClip;

void main() {
    vWorld = aPosition;
    vDepth = aDepth;
    vClip = uViewProjection * vec4(aPosition, 1.0);
    gl_Position = vClip;
}
