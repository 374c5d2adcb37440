#include "wind.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor; // rgb and the material's id (meshes with rgb only read 1: plain)

uniform mat4 uViewProjection;
// Water reflection/refraction keep one side of z = 0: distance = dot(plane, world); (0,0,0,1) keeps all.
uniform vec4 uClipPlane;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;
out float vMaterial;

// The balls' shadows redraw these surfaces within a scissor at GL_LEQUAL (SceneRenderer): the depth must match exactly.
invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 normal = uNormalMatrix * aNormal;
    waveCloth(aColor.a, world.xyz, normal);
    vWorld = world.xyz;
    vNormal = normal;
    vColor = aColor.rgb;
    vMaterial = aColor.a;
    gl_ClipDistance[0] = dot(uClipPlane, world);
    gl_Position = uViewProjection * world;
}
