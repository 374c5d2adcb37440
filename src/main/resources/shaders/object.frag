#include "lighting.glsl"
#include "shadow.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;

uniform float uSpecularStrength;
uniform float uShininess;
uniform vec3 uTint;      // multiplies the vertex colour (ball colours)

out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    // Thin things (the flag's cloth) are seen from both sides.
    if (dot(n, uEye - vWorld) < 0.0) n = -n;
    float sun = sunVisibility(vWorld, n);
    fragColor = vec4(haze(shadeLit(vColor * uTint, n, vWorld, uSpecularStrength, uShininess, sun), vWorld), 1.0);
}
