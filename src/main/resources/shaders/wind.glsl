// The flag's cloth waves (ObstacleMeshes.Material.CLOTH, id 6): travelling waves run out from the pole
// along the cloth, growing towards its free end; the normal tilts with the wave's slope. Everything
// else stands still. Deterministic in the frame's time (screenshots use t = 0).
uniform float uTime;
uniform vec2 uFlagPole; // the pole's x, y

void waveCloth(float material, inout vec3 world, inout vec3 normal) {
    if (material < 5.5) return;
    vec2 out2 = world.xy - uFlagPole;
    float d = length(out2);
    vec2 along = d > 1e-4 ? out2 / d : vec2(1.0, 0.0);
    vec2 side = vec2(-along.y, along.x);
    float phase = 14.0 * d - 4.2 * uTime;
    float amp = 0.11 * d;
    world.xy += side * amp * sin(phase) + along * (-0.02 * d * (1.0 - cos(phase)));
    world.z += 0.012 * d * sin(phase * 0.5 + 1.3);
    float slope = 0.11 * sin(phase) + amp * 14.0 * cos(phase);
    vec3 n = normal;
    float s = dot(n.xy, side);
    normal = normalize(vec3(n.xy - along * slope * s, n.z));
}
