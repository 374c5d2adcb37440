// The meadow and the trees round the course (SurroundingsPass): lit per vertex (the meadow is flat,
// the trees are small on screen), never shadowed; surroundings.frag fades them into the sky's haze.
#include "lighting.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProjection;
uniform vec4 uClipPlane;

out vec3 vWorld;
out vec3 vLit;

void main() {
    vec4 world = vec4(aPosition, 1.0);
    vLit = shade(aColor, normalize(aNormal), aPosition, 0.03, 8.0);
    vWorld = aPosition;
    gl_ClipDistance[0] = dot(uClipPlane, world);
    gl_Position = uViewProjection * world;
}
