// The sky's gradient and the sun's glow in a view direction: sky.vert draws them, surroundings.frag
// fades the far meadow into the same colours so its edge never shows.
// The colours are the world's (Atmosphere, from its theme).
uniform vec3 uSkyZenith;
uniform vec3 uSkyHorizon;
uniform vec3 uSkyBelow;
uniform vec3 uSunGlowColor;

vec3 skyGradient(vec3 dir) {
    float up = dir.z;
    return up >= 0.0 ? mix(uSkyHorizon, uSkyZenith, pow(max(up, 0.0), 0.55)) : mix(uSkyHorizon, uSkyBelow, clamp(-up * 1.6, 0.0, 1.0));
}

// The glow and halo round the sun; s = max(dot(dir, sun), 0).
vec3 sunGlow(float s) {
    return uSunGlowColor * (pow(s, 300.0) * 0.6 + pow(s, 12.0) * 0.15);
}
