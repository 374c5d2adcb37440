// Mowing stripes on the grass (TerrainMesh.STRIPE_WIDTH = 0.5 m wide across x from the course's edge,
// every other one STRIPE_SHADE = 0.92 as bright), per pixel and box-filtered over the pixel's
// footprint, so that far away they fade to their mean instead of aliasing; the terrain's level of
// detail spaces far vertices wider than a stripe. `weight` is the vertex's share of grass (1 - sand).
uniform float uStripeOrigin;

// The length of bright stripe in [0, u] (u in stripe widths; stripes 0, 2, 4, ... are bright).
float brightLength(float u) {
    return floor(u * 0.5) + min(fract(u * 0.5) * 2.0, 1.0);
}

float stripeFactor(float x, float weight) {
    float u = (x - uStripeOrigin) / 0.5;
    float w = max(fwidth(u), 1e-3);
    float bright = (brightLength(u + 0.5 * w) - brightLength(u - 0.5 * w)) / w;
    return mix(1.0, mix(0.92, 1.0, clamp(bright, 0.0, 1.0)), weight);
}
