layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor; // rgb, and the mowing stripes' weight (stripes.glsl)

uniform mat4 uViewProjection;
// Water reflection/refraction keep one side of z = 0: distance = dot(plane, world); (0,0,0,1) keeps all.
uniform vec4 uClipPlane;

out vec3 vWorld;
out vec3 vNormal;
out vec3 vColor;
out float vStripes;

// The balls' shadows redraw these surfaces within a scissor at GL_LEQUAL (SceneRenderer): the depth must match exactly.
invariant gl_Position;

void main() {
    vWorld = aPosition;
    vNormal = aNormal;
    vColor = aColor.rgb;
    vStripes = aColor.a;
    gl_ClipDistance[0] = dot(uClipPlane, vec4(aPosition, 1.0));
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
