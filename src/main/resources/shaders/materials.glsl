// Materials (MaterialTextures): tiling detail layers made in code (MaterialPatterns: grass, sand,
// wood, stone, rock, snow; rgb a brightness/tint factor stored halved, alpha a height) and the
// course's ground occlusion (OcclusionMap). One texture read per surface pixel; the high tier adds
// bump normals from the heights (screen-space derivatives, no tangents needed) and the occlusion.
uniform sampler2DArray uMaterials;
uniform sampler2D uOcclusion;
uniform vec4 uOcclusionRect; // min x, min y, 1 / width, 1 / depth of the course's bounds
uniform float uEdgeLayer;    // the course edge's layer (the world's)
uniform float uSandLayer;    // what rough zones show: sand, or snow in a winter world

const float LAYER_GRASS = 0.0;
const float LAYER_WOOD = 2.0;
const float LAYER_STONE = 3.0;
const float LAYER_ROCK = 4.0;
const float LAYER_MOTTLE = 6.0;

// Large soft patches (lighter, drier; darker, lusher) at the world point p, about 3 m across.
vec3 mottleAt(vec2 p) {
    return texture(uMaterials, vec3(p * 0.06, LAYER_MOTTLE)).rgb * 2.0;
}

// The layer's factor (rgb, 1 = the material's own colour) and height (a) at uv.
vec4 materialAt(vec2 uv, float layer) {
    vec4 t = texture(uMaterials, vec3(uv, layer));
    return vec4(t.rgb * 2.0, t.a);
}

// The sky light that reaches the ground at xy (1 open, lower at the foot of rails and boxes).
float groundOcclusion(vec2 xy) {
    return texture(uOcclusion, (xy - uOcclusionRect.xy) * uOcclusionRect.zw).r;
}

// Texture coordinates along a vertical face with normal n: metres along it, and height.
vec2 alongFace(vec3 p, vec3 n) {
    vec2 t = n.xy + vec2(1e-4, 0.0);
    t = normalize(vec2(-t.y, t.x));
    return vec2(dot(p.xy, t), p.z);
}

// The terrain's detail. code: the vertex's grass share (0..1; sand, lake bed and ice are 0), or 2
// on the course's edge (its side walls), which shows the world's rock or stone in horizontal courses.
vec4 groundDetail(vec3 p, vec3 n, float code) {
    float edge = step(1.5, code);
    float layer = edge > 0.5 ? uEdgeLayer : (code > 0.5 ? LAYER_GRASS : uSandLayer);
    vec2 uv = edge > 0.5 ? alongFace(p, n) * vec2(0.5, 1.0) : p.xy * 2.0;
    return materialAt(uv, layer);
}

// An obstacle's detail by its material (ObstacleMeshes.Material: 1 plain, 2 wood, 3 painted wood,
// 4 stone, 5 sandstone): along the face for walls (grain and courses run along the rail), from
// above on tops. Plain surfaces keep their colour (factor 1, flat).
vec4 obstacleDetail(vec3 p, vec3 n, float material) {
    float stone = step(3.5, material);
    float layer = stone > 0.5 ? LAYER_STONE : LAYER_WOOD;
    vec2 side = alongFace(p, n);
    vec2 uv = abs(n.z) > 0.92 ? p.xy : side;
    uv *= stone > 0.5 ? vec2(1.6, 3.3) : vec2(1.0, 5.0);
    vec4 d = materialAt(uv, layer);
    float strength = material < 1.5 ? 0.0 : (material < 2.5 ? 1.0 : (material < 3.5 ? 0.3 : 1.0));
    return vec4(mix(vec3(1.0), d.rgb, strength), d.a * strength);
}

// The normal n bent by a height field h (metres) over the surface at p: Mikkelsen's bump mapping
// from screen-space derivatives, so no tangents are needed.
vec3 bumped(vec3 p, vec3 n, float h) {
    vec3 dpdx = dFdx(p), dpdy = dFdy(p);
    float dhdx = dFdx(h), dhdy = dFdy(h);
    vec3 r1 = cross(dpdy, n), r2 = cross(n, dpdx);
    float det = dot(dpdx, r1);
    if (abs(det) < 1e-12) return n;
    vec3 grad = sign(det) * (dhdx * r1 + dhdy * r2);
    return normalize(abs(det) * n - grad);
}
