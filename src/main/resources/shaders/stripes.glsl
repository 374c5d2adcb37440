// Mowing stripes on the grass (TerrainMesh.STRIPE_WIDTH = 0.5 m wide across x from the course's edge,
// every other one STRIPE_SHADE = 0.92 as bright), per pixel and box-filtered over the pixel's
// footprint, so that far away they fade to their mean instead of aliasing; the terrain's level of
// detail spaces far vertices wider than a stripe. `weight` is the vertex's share of grass (1 - sand).
uniform float uStripeOrigin;
uniform float uStripeShade; // the darker stripes' brightness (the world's; Meadowbrook's 0.92)

float stripeFactor(float x, float weight) {
    float u = (x - uStripeOrigin) * 2.0;          // in stripe widths; bright stripes are [0, 1) mod 2
    float c = abs(mod(u + 0.5, 2.0) - 1.0);       // distance from the nearest bright stripe's centre, 0..1
    float w = max(fwidth(u), 1e-3);                // the pixel's footprint in stripe widths
    float bright = clamp(0.5 + (0.5 - c) / w, 0.0, 1.0); // box filter of the edge (0.5 mean when w is large)
    return mix(1.0, mix(uStripeShade, 1.0, bright), weight);
}
