// The course's haze near by, then, with the horizontal distance from the eye, the sky's own colour in
// this direction (sky-colour.glsl), so the meadow melts into the sky below the horizon.
#include "lighting.glsl"
#include "sky-colour.glsl"

in vec3 vWorld;
in vec3 vLit;

uniform vec2 uFade; // horizontal distances where the fade starts and where it is complete

out vec4 fragColor;

void main() {
    vec3 d = vWorld - uEye;
    vec3 dir = normalize(d);
    vec3 far = skyGradient(dir) + sunGlow(max(dot(dir, normalize(uSunDirection)), 0.0));
    float f = smoothstep(uFade.x, uFade.y, length(d.xy));
    fragColor = vec4(mix(haze(vLit, vWorld), far, f), 1.0);
}
