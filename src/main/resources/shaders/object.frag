// Objects and obstacles at high quality: per-pixel light; rails and boxes show their material
// (materials.glsl: wood grain, painted boards, stone courses) with bump normals.
#include "lighting.glsl"
#include "shadow.glsl"
#include "materials.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
in float vMaterial;

uniform float uSpecularStrength;
uniform float uShininess;
uniform vec3 uTint;      // multiplies the vertex colour (ball colours)

out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    // Thin things (the flag's cloth) are seen from both sides.
    if (dot(n, uEye - vWorld) < 0.0) n = -n;
    float sun = sunVisibility(vWorld, n);
    vec3 albedo = vColor * uTint;
    vec3 lit = n;
    if (vMaterial > 1.5) {
        vec4 detail = obstacleDetail(vWorld, n, vMaterial);
        albedo *= detail.rgb;
        lit = bumped(vWorld, n, detail.a * 0.004);
    }
    fragColor = vec4(haze(shadeLit(albedo, lit, vWorld, uSpecularStrength, uShininess, sun), vWorld), 1.0);
}
