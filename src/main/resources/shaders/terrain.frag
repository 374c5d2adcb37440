#include "lighting.glsl"
#include "shadow.glsl"
#include "stripes.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
in float vStripes;

uniform float uSpecularStrength;
uniform float uShininess;

out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    vec3 color = shadeLit(vColor * stripeFactor(vWorld.x, vStripes), n, vWorld, uSpecularStrength, uShininess, sunVisibility(vWorld, n));
    fragColor = vec4(haze(color, vWorld), 1.0);
}
