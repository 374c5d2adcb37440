#include "lighting.glsl"
#ifdef BED_BLEND
#include "sky-colour.glsl"
#endif

// Water at z = 0. With render targets (uUseTargets = 1): the scene mirrored in z = 0 (reflection)
// and the lake bed under the surface (refraction), both sampled at this pixel's screen position,
// shifted by an animated du/dv ripple map; Fresnel mixes them (mostly refraction looking down,
// mostly reflection at grazing angles). Water depth tints and darkens the refraction and fades
// the shoreline. Without targets (the minimap, or reflections off) a sky colour and a body colour
// stand in for the two images.
// BED_BLEND (software rasterisers; WaterPass): no images at all. The reflection is the sky's gradient
// in the rippled mirror direction, and the bed is the one already drawn behind the water: dual-source
// blending (fragColor + destination x bedFactor) tints and darkens it exactly as the refraction image
// would be, only not shifted by the ripples.

in vec3 vWorld;
in float vDepth;
in vec4 vClip;

uniform float uTime;
uniform int uUseTargets;
uniform sampler2D uReflection;
uniform sampler2D uRefraction;
uniform sampler2D uDudv;
uniform float uDistortion;   // ripple strength in screen-space units

#ifdef BED_BLEND
layout(location = 0, index = 0) out vec4 fragColor;
layout(location = 0, index = 1) out vec4 bedFactor;
#else
out vec4 fragColor;
#endif

const vec3 SHALLOW = vec3(0.10, 0.52, 0.74);
const vec3 DEEP = vec3(0.04, 0.24, 0.52);
const vec3 SKY = vec3(0.62, 0.78, 0.95);

void main() {
    vec3 v = normalize(uEye - vWorld);
    // Two layers of the ripple map drifting in different directions (metres -> texture repeats).
    vec2 p = vWorld.xy * 0.45;
    vec2 d1 = texture(uDudv, p + vec2(0.021, 0.013) * uTime).rg * 2.0 - 1.0;
    vec2 d2 = texture(uDudv, p * 1.7 + vec2(-0.017, 0.026) * uTime + vec2(0.37, 0.61)).rg * 2.0 - 1.0;
    vec2 slope = d1 + 0.6 * d2;
    vec3 n = normalize(vec3(-slope * 0.06, 1.0));

    float deep = 1.0 - exp(-vDepth * 40.0);
    // Less ripple where the water is only a film, so the shore does not shimmer over dry pixels.
    float shore = smoothstep(0.0, 0.02, vDepth);

    vec3 body = mix(SHALLOW, DEEP, deep);
#ifdef BED_BLEND
    vec3 reflectedSky = skyGradient(reflect(-v, n));
    float mirror = clamp((0.02 + 0.98 * pow(1.0 - clamp(dot(n, v), 0.0, 1.0), 5.0)) * 1.3, 0.0, 1.0);
    float murk = 0.55 + 0.32 * deep;                       // the body colour's share of the refraction
    vec3 glint = uSunColor * pow(max(dot(n, normalize(normalize(uSunDirection) + v)), 0.0), 220.0) * 0.8 * shore;
    vec3 own = (1.0 - mirror) * murk * body + mirror * reflectedSky + glint;
    float fog = hazeAmount(length(uEye - vWorld));
    float cover = smoothstep(0.0, 0.006, vDepth);          // the soft shoreline
    fragColor = vec4(cover * mix(own, uFogColor, fog), 1.0);
    bedFactor = vec4(cover * (1.0 - fog) * (1.0 - mirror) * (1.0 - murk) * vec3(0.55, 0.85, 0.95) + (1.0 - cover), 1.0);
    return;
#endif
    vec3 reflected;
    vec3 refracted;
    if (uUseTargets == 1) {
        vec2 screen = vClip.xy / vClip.w * 0.5 + 0.5;
        vec2 offset = slope * uDistortion * shore;
        reflected = texture(uReflection, clamp(screen + offset, 0.001, 0.999)).rgb;
        vec3 bed = texture(uRefraction, clamp(screen + offset * 0.6, 0.001, 0.999)).rgb;
        // Light through water: the bed takes the water's colour, more so the deeper it lies.
        refracted = mix(bed * vec3(0.55, 0.85, 0.95), body, 0.55 + 0.32 * deep);
    } else {
        reflected = SKY;
        refracted = body;
    }
    float cosTheta = clamp(dot(n, v), 0.0, 1.0);
    float fresnel = 0.02 + 0.98 * pow(1.0 - cosTheta, 5.0);
    vec3 color = mix(refracted, reflected, clamp(fresnel * 1.3, 0.0, 1.0));
    vec3 h = normalize(normalize(uSunDirection) + v);
    color += uSunColor * pow(max(dot(n, h), 0.0), 220.0) * 0.8 * shore;

    float alpha = uUseTargets == 1 ? 1.0 : max(mix(0.80, 0.95, deep), fresnel);
    alpha *= smoothstep(0.0, 0.006, vDepth); // soft shoreline
    fragColor = vec4(haze(color, vWorld), alpha);
}
