// The terrain for software rasterisers (RenderQuality.SOFTWARE): the sun's lighting, the haze and the
// shadow-map coordinates are computed per vertex (the mesh is 5 cm fine, so Gouraud shading looks
// the same as per-pixel on a putting green) and interpolated; the fragment shader keeps only the
// shadow-map tap and the balls' analytic shadows, which must stay sharp per pixel. The light's
// projection is orthographic (affine), so interpolating its coordinates is exact.
#include "lighting.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor; // rgb, and the mowing stripes' weight (stripes.glsl)

uniform mat4 uViewProjection;
uniform vec4 uClipPlane;
uniform mat4 uLightViewProjection;
uniform float uShadowNormalOffset;
uniform float uSpecularStrength;
uniform float uShininess;

out vec3 vWorld;
out vec3 vUnlit;     // ambient part, never shadowed
out vec3 vSunlit;    // sun diffuse + specular, scaled by the sun's visibility per pixel
out vec3 vShadowCoord;
out float vHaze;
out float vStripes;

// The balls' shadows redraw these surfaces within a scissor at GL_LEQUAL (SceneRenderer): the depth must match exactly.
invariant gl_Position;

void main() {
    vec3 n = normalize(aNormal);
    vec3 v = normalize(uEye - aPosition);
    vec3 l = normalize(uSunDirection);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.z);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), uShininess) : 0.0;
    vUnlit = aColor.rgb * ambient;
    vSunlit = aColor.rgb * uSunColor * diffuse + uSunColor * specular * uSpecularStrength;
#if !defined(SHADOW_MAP) && !defined(BALL_SHADOWS)
    // Nothing shadows this draw (sunlit cells, faces turned from the sun, shadows off): the sunlight is
    // added here, and the fragment stage interpolates three inputs fewer (vertexlit-fragment.glsl).
    vUnlit += vSunlit;
#endif
    vHaze = hazeAmount(length(uEye - aPosition));
    vec4 p = uLightViewProjection * vec4(aPosition + n * uShadowNormalOffset, 1.0);
    vShadowCoord = p.xyz / p.w * 0.5 + 0.5;
    vWorld = aPosition;
    vStripes = aColor.a;
    gl_ClipDistance[0] = dot(uClipPlane, vec4(aPosition, 1.0));
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
