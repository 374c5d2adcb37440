// A procedural sky dome, computed at the corners of a screen-covering grid at the far plane (SkyPass):
// the gradient (deep blue zenith, pale horizon), the sun's glow and halo, and drifting fair-weather
// clouds (fractal value noise baked into a tiling texture, CloudNoise, on a cloud layer: the view
// direction projected onto a plane above), faded out towards the horizon. Below the horizon a hazy
// far distance, darker than the sky, so the course reads as floating above a valley. All of that
// varies slowly over the screen, so it is computed per grid corner and interpolated: a software
// rasteriser then pays little per pixel (sky.frag keeps the clouds' edges and the sun's disc sharp).
#include "lighting.glsl"
#include "sky-colour.glsl"

layout(location = 0) in vec2 aNdc;

uniform mat4 uInverseViewProjection;
uniform float uTime;
uniform sampler2D uClouds;
uniform float uCloudPeriod;
uniform float uCloudTexels;  // texels per side of uClouds
uniform vec2 uGridStep;      // one grid cell in NDC
uniform float uGridPixels;   // one grid cell in pixels (about)
uniform float uCut;          // 1: the corners drawn are the shore's small cells' (SkyPass), inside the grid's cells
// The meadow round the course (SurroundingsPass), a plane at height uGround.x when uGround.y is 1: its
// colour varies slowly over the screen too (flat, unshadowed), so it is computed here per corner
// instead of costing llvmpipe a depth-tested fill of half the screen (about 2 ms a frame).
uniform vec2 uGround;
uniform vec3 uGroundColor;
uniform vec2 uFade;          // horizontal distances over which the meadow fades into the sky
#ifdef SEA
// A seaside world: the ground ends at a beach round the course and the sea reaches to the horizon.
// Their colours are computed here; which of them a pixel shows is decided per pixel (sky.frag,
// SEA_PIXEL) in the cells wholly below the horizon, per corner in the others (they lie far away).
uniform vec3 uSeaColor;
uniform vec3 uBeachColor;
uniform vec4 uCourseRect;    // the course's bounds: min x, min y, max x, max y
uniform float uShore;        // the shore's distance from the bounds (metres)
out vec3 vSea;
out vec3 vBeach;
#endif

out vec3 vSky;        // gradient under the clouds
out vec3 vCloudColor; // the sun's warm tint on the clouds here
out vec2 vCloudUv;    // where the cloud texture is read, per pixel
out float vCloudLod;  // at which mip level
out float vCloudAlpha;// how much cloud shows (fades towards the horizon; none below it)
out vec3 vGlow;       // the sun's glow and halo, over the clouds
out vec3 vDir;        // the view direction, for the sun's disc per pixel

// From the near plane's point to the far plane's under ndc: both planes' points are linear in ndc, so
// unnormalised this ray interpolates to each pixel's exact ray.
vec3 rayAt(vec2 ndc) {
    vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
    return farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w;
}

vec3 directionAt(vec2 ndc) {
    return normalize(rayAt(ndc));
}

// Clouds on a layer 1 unit up: dir.xy / dir.z, drifting with time; in texture units.
vec2 cloudUv(vec3 dir) {
    vec2 uv = dir.xy / max(dir.z, 0.04) * 0.9 + vec2(uTime * 0.004, uTime * 0.0025);
    return uv * 1.4 / uCloudPeriod;
}

// The sky's colours at screen point ndc (a grid corner) into the outputs.
void skyAt(vec2 ndc) {
    vec3 dir = directionAt(ndc);
    vec3 sun = normalize(uSunDirection);
    float up = dir.z;
    float s = max(dot(dir, sun), 0.0);

    vSky = skyGradient(dir);
    vGlow = sunGlow(s);
    vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec3 origin = nearPoint.xyz / nearPoint.w;
#ifdef SEA
    vSea = vSky;
    vBeach = vSky;
#endif
    if (uGround.y > 0.5 && up < 0.0 && origin.z > uGround.x) {
        vec3 p = origin + dir * ((uGround.x - origin.z) / up);
        vec3 lit = haze(shade(uGroundColor, vec3(0.0, 0.0, 1.0), p, 0.03, 8.0), p);
        float f = smoothstep(uFade.x, uFade.y, length(p.xy - uEye.xy));
#ifdef SEA
        // The sea: the sky mirrored (Fresnel) over deep water, and a broad glint towards the sun.
        vec3 r = reflect(dir, vec3(0.0, 0.0, 1.0));
        float fresnel = 0.02 + 0.98 * pow(1.0 - max(-up, 0.0), 5.0);
        vec3 sea = mix(uSeaColor * (uSkyAmbient + uSunColor * 0.35), skyGradient(r), clamp(fresnel * 1.2, 0.0, 1.0));
        sea += uSunColor * pow(max(dot(r, sun), 0.0), 40.0) * 0.35;
        vSea = mix(haze(sea, p), vSky, f);
        vBeach = mix(haze(shade(uBeachColor, vec3(0.0, 0.0, 1.0), p, 0.03, 8.0), p), vSky, f);
#ifndef SEA_PIXEL
        vec2 outside = max(max(uCourseRect.xy - p.xy, p.xy - uCourseRect.zw), 0.0);
        // (The shore's small cells pick sea or land for themselves, main below.)
        if (uCut < 0.5 && length(outside) > uShore) lit = haze(sea, p);
#endif
#endif
        vSky = mix(lit, vSky, f);
        vGlow *= f; // the fragment adds it: mix(lit, sky + glow, f) in all
    }

    // The noise is read at a mip level as coarse as the grid: finer detail could not be interpolated anyway.
    vec2 uv = cloudUv(dir);
    vec2 du = cloudUv(directionAt(ndc + vec2(uGridStep.x, 0.0))) - uv;
    vec2 dv = cloudUv(directionAt(ndc + vec2(0.0, uGridStep.y))) - uv;
    vCloudLod = log2(max(max(length(du), length(dv)) * uCloudTexels / uGridPixels, 1.0));
    vCloudUv = uv;
    vCloudColor = vec3(1.0, 0.9, 0.7) * pow(s, 8.0) * 0.25;
    vCloudAlpha = up >= 0.0 ? smoothstep(0.02, 0.25, up) * 0.9 : 0.0;
#if !defined(CLOUDS) && !defined(SEA_PIXEL) && !defined(GROUND_DETAIL)
    // Nothing per pixel goes between the gradient and the glow: one colour to interpolate (sky.frag).
    vSky += vGlow;
#endif
}

// A weighted sum of the outputs (w: this corner's weight, first: the first corner).
vec3 oSky, oCloudColor, oGlow, oSea, oBeach;
vec2 oCloudUv;
float oCloudLod, oCloudAlpha;

void addCorner(vec2 ndc, float w, bool first) {
    skyAt(ndc);
    float k = first ? 0.0 : 1.0;
    oSky = oSky * k + vSky * w;
    oCloudColor = oCloudColor * k + vCloudColor * w;
    oGlow = oGlow * k + vGlow * w;
    oCloudUv = oCloudUv * k + vCloudUv * w;
    oCloudLod = oCloudLod * k + vCloudLod * w;
    oCloudAlpha = oCloudAlpha * k + vCloudAlpha * w;
#ifdef SEA
    oSea = oSea * k + vSea * w;
    oBeach = oBeach * k + vBeach * w;
#endif
}

void main() {
    if (uCut < 0.5) {
        skyAt(aNdc);
    } else {
        // A corner of the shore's small cells (SkyPass): its colours are those the big cell's two triangles
        // (a b d and a d c) interpolate there, so the small cells meet the big ones without a seam.
        vec2 cells = 2.0 / uGridStep;
        vec2 cell = clamp(floor((aNdc + 1.0) / uGridStep), vec2(0.0), cells - 1.0);
        vec2 f = clamp((aNdc + 1.0) / uGridStep - cell, 0.0, 1.0);
        vec2 a = cell * uGridStep - 1.0;
        vec2 d = a + uGridStep;
        if (f.x >= f.y) {
            addCorner(a, 1.0 - f.x, true);
            addCorner(vec2(d.x, a.y), f.x - f.y, false);
        } else {
            addCorner(a, 1.0 - f.y, true);
            addCorner(vec2(a.x, d.y), f.y - f.x, false);
        }
        addCorner(d, min(f.x, f.y), false);
        vSky = oSky;
        vCloudColor = oCloudColor;
        vGlow = oGlow;
        vCloudUv = oCloudUv;
        vCloudLod = oCloudLod;
        vCloudAlpha = oCloudAlpha;
#ifdef SEA
        vSea = oSea;
        vBeach = oBeach;
#ifndef SEA_PIXEL
        // A small cell off the band is all land or all sea: this corner's own point of the ground says which.
        vec4 n = uInverseViewProjection * vec4(aNdc, -1.0, 1.0);
        vec3 o = n.xyz / n.w, r = rayAt(aNdc);
        if (r.z < 0.0 && o.z > uGround.x) {
            vec2 p = o.xy + r.xy * ((uGround.x - o.z) / r.z);
            vec2 outside = max(max(uCourseRect.xy - p, p - uCourseRect.zw), 0.0);
            if (length(outside) > uShore) vSky = oSea + oGlow;
        }
#endif
#endif
    }
#ifdef GROUND_DETAIL
    vDir = directionAt(aNdc);
#else
    // The software tier's shore is found per pixel from this ray (sky.frag normalises it): the exact ray
    // puts it where it is whatever the size of the cell drawn (SkyPass cuts the shore's cells smaller).
    vDir = rayAt(aNdc);
#endif
    gl_Position = vec4(aNdc, 1.0, 1.0);
}
