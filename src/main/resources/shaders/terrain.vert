layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProjection;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;

void main() {
    vWorld = aPosition;
    vNormal = aNormal;
    vColor = aColor;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
