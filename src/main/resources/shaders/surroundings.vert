// The meadow and the trees round the course (SurroundingsPass), all per vertex: llvmpipe paid about
// 6 ms a frame for the same per pixel over the meadow's half of the screen. Lit (the meadow is flat,
// the trees small), never shadowed, then the course's haze and, with the horizontal distance from
// the eye, the sky's own colour in this direction (sky-colour.glsl), so the meadow melts into the
// sky below the horizon. The meadow's rings are dense enough for the fade to interpolate smoothly.
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
