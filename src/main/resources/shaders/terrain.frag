// The terrain at high quality: per-pixel light, the material's detail (materials.glsl: grass, sand or
// snow, the edge's rock or stone), bump normals from its heights, and the ground's occlusion at the
// foot of rails and boxes.
#include "lighting.glsl"
#include "shadow.glsl"
#include "stripes.glsl"
#include "materials.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec3 vColor;
in float vStripes; // the grass share, or 2 on the course's edge (TerrainMesh.EDGE_CODE)

uniform float uSpecularStrength;
uniform float uShininess;

out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    float edge = step(1.5, vStripes);
    vec4 detail = groundDetail(vWorld, n, vStripes);
    // Bumps: a few millimetres on the green, a couple of centimetres on the rock of the edge.
    vec3 lit = bumped(vWorld, n, detail.a * mix(0.0025, 0.02, edge));
    float grass = vStripes * (1.0 - edge);
    float occlusion = mix(groundOcclusion(vWorld.xy), 1.0, edge);
    // Patches over the ground (not the edge): the fine tile does not repeat visibly.
    vec3 patches = mix(mottleAt(vWorld.xy), vec3(1.0), edge);
    vec3 albedo = vColor * detail.rgb * patches * stripeFactor(vWorld.x, grass);
    vec3 color = shadeOccluded(albedo, lit, vWorld, uSpecularStrength, uShininess, sunVisibility(vWorld, n), occlusion);
    fragColor = vec4(haze(color, vWorld), 1.0);
}
