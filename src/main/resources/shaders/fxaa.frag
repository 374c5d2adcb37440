// Fast approximate anti-aliasing (after Timothy Lottes' FXAA, the compact "PC" variant, cut down
// for software rasterisers): where there is no MSAA the finished scene is drawn into an image and
// copied to the screen through this filter (FxaaPass; a setting, off by default). Per pixel: the
// luma of the four diagonal neighbours (unfiltered fetches) gives the edge's direction, and a pixel
// on an edge becomes the mean of two filtered taps along it, up to FXAA_SPAN_MAX pixels away. Flat
// pixels (a small luma range) are copied unchanged. FXAA's wider four-tap blend was left out: on
// llvmpipe the whole filter cost 21 ms a frame at 1280x720 with filtered luma taps and the wide blend.
in vec2 vUv;
uniform sampler2D uImage;
uniform vec2 uTexel; // 1 / image size

out vec4 fragColor;

const float FXAA_REDUCE_MIN = 1.0 / 128.0;
const float FXAA_REDUCE_MUL = 1.0 / 8.0;
const float FXAA_SPAN_MAX = 8.0;
// Below this local contrast (absolute, or relative to the brightest neighbour) a pixel is left alone.
const float EDGE_THRESHOLD = 1.0 / 8.0;
const float EDGE_THRESHOLD_MIN = 1.0 / 32.0;

float luma(vec3 c) {
    return dot(c, vec3(0.299, 0.587, 0.114));
}

void main() {
    // The five luma taps land on texel centres: unfiltered fetches (cheaper on a software rasteriser).
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uImage, 0) - 1;
    vec3 rgbM = texelFetch(uImage, p, 0).rgb;
    float lumaNW = luma(texelFetch(uImage, clamp(p + ivec2(-1, -1), ivec2(0), last), 0).rgb);
    float lumaNE = luma(texelFetch(uImage, clamp(p + ivec2(1, -1), ivec2(0), last), 0).rgb);
    float lumaSW = luma(texelFetch(uImage, clamp(p + ivec2(-1, 1), ivec2(0), last), 0).rgb);
    float lumaSE = luma(texelFetch(uImage, clamp(p + ivec2(1, 1), ivec2(0), last), 0).rgb);
    float lumaM = luma(rgbM);
    float lumaMin = min(lumaM, min(min(lumaNW, lumaNE), min(lumaSW, lumaSE)));
    float lumaMax = max(lumaM, max(max(lumaNW, lumaNE), max(lumaSW, lumaSE)));
    if (lumaMax - lumaMin < max(EDGE_THRESHOLD_MIN, lumaMax * EDGE_THRESHOLD)) {
        fragColor = vec4(rgbM, 1.0);
        return;
    }
    vec2 dir = vec2(-((lumaNW + lumaNE) - (lumaSW + lumaSE)), (lumaNW + lumaSW) - (lumaNE + lumaSE));
    float dirReduce = max((lumaNW + lumaNE + lumaSW + lumaSE) * (0.25 * FXAA_REDUCE_MUL), FXAA_REDUCE_MIN);
    float rcpDirMin = 1.0 / (min(abs(dir.x), abs(dir.y)) + dirReduce);
    dir = clamp(dir * rcpDirMin, vec2(-FXAA_SPAN_MAX), vec2(FXAA_SPAN_MAX)) * uTexel;
    // Two filtered taps along the edge (FXAA's narrow blend; its wider four-tap blend cost llvmpipe
    // about as much again).
    vec3 rgbA = 0.5 * (texture(uImage, vUv + dir * (1.0 / 3.0 - 0.5)).rgb
                     + texture(uImage, vUv + dir * (2.0 / 3.0 - 0.5)).rgb);
    fragColor = vec4(rgbA, 1.0);
}
