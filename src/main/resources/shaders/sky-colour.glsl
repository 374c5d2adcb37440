// The sky's gradient and the sun's glow in a view direction: sky.vert draws them, surroundings.frag
// fades the far meadow into the same colours so its edge never shows.
vec3 skyGradient(vec3 dir) {
    vec3 horizon = vec3(0.80, 0.88, 0.96);
    vec3 zenith = vec3(0.22, 0.45, 0.82);
    vec3 below = vec3(0.55, 0.70, 0.88);
    float up = dir.z;
    return up >= 0.0 ? mix(horizon, zenith, pow(max(up, 0.0), 0.55)) : mix(horizon, below, clamp(-up * 1.6, 0.0, 1.0));
}

// The glow and halo round the sun; s = max(dot(dir, sun), 0).
vec3 sunGlow(float s) {
    return vec3(1.0, 0.95, 0.80) * (pow(s, 300.0) * 0.6 + pow(s, 12.0) * 0.15);
}
