// The decorative trees round the course (SurroundingsPass), all per vertex (they are small on screen):
// lit, never shadowed, then the course's haze and, with the horizontal distance from the eye, the
// sky's own colour in this direction (sky-colour.glsl), as sky.vert fades the meadow they stand on.
#include "lighting.glsl"
#include "sky-colour.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;

uniform mat4 uViewProjection;
uniform vec4 uClipPlane;
uniform vec2 uFade; // horizontal distances where the fade starts and where it is complete

out vec3 vColor;

void main() {
    vec4 world = vec4(aPosition, 1.0);
    vec3 lit = haze(shade(aColor, normalize(aNormal), aPosition, 0.03, 8.0), aPosition);
    vec3 d = aPosition - uEye;
    vec3 dir = normalize(d);
    vec3 far = skyGradient(dir) + sunGlow(max(dot(dir, normalize(uSunDirection)), 0.0));
    vColor = mix(lit, far, smoothstep(uFade.x, uFade.y, length(d.xy)));
    gl_ClipDistance[0] = dot(uClipPlane, world);
    gl_Position = uViewProjection * world;
}
