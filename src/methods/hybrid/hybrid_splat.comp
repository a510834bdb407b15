// The forward phase of the hybrid method (the hybrid paper, §6): every point of every kd-tree
// leaf that survived a C3RC's culling is projected with that C3RC — all of its projections, or
// the first only (--hybrid-projections first, the paper's one fragment per point) — and splatted
// as an s×s square at the reflector point that sees it — or, with a level of detail, a uniform
// stride through them with proportionally larger splats. Visibility: a splat on another
// reflector's pixel (beside its own's silhouette) or behind the visible reflector surface at its
// pixel is dropped (another part of the reflector hides it); the rest
// keep the nearest push-back per pixel with one atomicMin on its float bits, and a splat at least
// as near as the pixel's word was appends itself as a candidate for hybrid_winner.comp, which
// picks the nearest's index (hybrid_shared.h).
#include "render/shaders/common.glsl"
#include "methods/hybrid/c3rc_shared.h"
#include "methods/hybrid/hybrid_shared.h"

layout(local_size_x = MIRAGE_HYBRID_GROUP) in;

layout(std430, binding = MIRAGE_BIND_HYBRID_C3RCS) readonly buffer C3rcBlock { C3rcData c3rcs[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_ITEMS) readonly buffer ItemBlock { ivec4 items[]; };
// A run: its first item, the first of that item's taken points it projects, its last item and
// the end of that item's taken points it projects (splat_pass.h, SplatRun).
layout(std430, binding = MIRAGE_BIND_HYBRID_RUNS) readonly buffer RunBlock { ivec4 runs[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_POINTS) readonly buffer PointBlock {
  vec4 positions[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_POINT_ATTRIBUTES) readonly buffer AttributeBlock {
  PointAttributes attributes[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_SPLATS) coherent buffer SplatBlock { uint depths[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_COUNTERS) buffer CounterBlock { uint counters[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_CANDIDATES) writeonly buffer CandidateBlock {
  uint candidates[];
};
layout(std430, binding = MIRAGE_BIND_HYBRID_ITEM_SEEN) buffer SeenBlock { uint item_seen[]; };
layout(binding = MIRAGE_UNIT_HYBRID_DEPTH) uniform sampler2D u_depth;
// The reflector triangle each pixel shows (instance + 1, primitive; triangle_id.frag).
layout(binding = MIRAGE_UNIT_HYBRID_IDS) uniform usampler2D u_ids;

uniform int u_run_count;
uniform int u_run_base;  // the run of this dispatch's first workgroup
// > 0: the items are on the GPU, no runs given: run r is slice r % u_slices of item r / u_slices,
// u_slice_points of its points each.
uniform int u_slices;
uniform int u_slice_points;
uniform int u_first_only;          // 1: the first projection only
uniform int u_splat_size;          // s: an s×s square; 0: from the magnification
uniform int u_pixel_scale;         // frame pixels per output pixel along a side (--ssaa)
uniform int u_candidate_capacity;  // candidates beyond it are counted, not written
uniform vec2 u_proj;               // the projection matrix's [2][2] and [3][2]: eye depth from z
uniform float u_occlusion;         // relative depth tolerance of the occlusion test
uniform int u_keep_backfaces;      // 1: project the back-facing points of closed objects too
// 1: count each item's points with a projection (item_seen) and splat nothing: the level of
// detail's probe (splat_pass.h).
uniform int u_count_only;

// The eye depth the reflector pass left at a pixel.
float surface_eye_depth(ivec2 pixel) {
  float z = texelFetch(u_depth, pixel, 0).r * 2.0f - 1.0f;
  return u_proj.y / (z + u_proj.x);
}

// The splat's side in pixels: fixed, or (u_splat_size = 0) the point spacing magnified to the
// screen — by the C3RC (c3rc_spread: its growth and tilts) and by the perspective at the
// reflector point — rounded up to whole output pixels (u_pixel_scale frame pixels each under
// --ssaa: a supersampled frame's splats then cover what the native frame's do), so that
// neighbouring points close the surface.
int splat_side(C3rcData c, vec4 proj, vec3 base, float spacing, float eye_depth) {
  if (u_splat_size > 0) return u_splat_size;
  float spread = c3rc_spread(c, proj, normalize(frame.eye.xyz - base));
  float on_screen = spacing / sqrt(max(spread, 1.0e-12f));
  float pixels = on_screen * frame.viewport.y / (2.0f * frame.viewport.z * max(eye_depth, 1.0e-6f));
  return clamp(int(ceil(pixels / float(u_pixel_scale))) * u_pixel_scale, u_pixel_scale,
               MIRAGE_HYBRID_MAX_SPLAT * u_pixel_scale);
}

uint splat(C3rcData c, vec4 proj, vec3 q, float spacing, uint index) {
  vec3 base = c3rc_base_point(c, proj);
  vec4 clip = frame.view_proj * vec4(base, 1.0f);
  if (clip.w <= 0.0f) return 0u;
  vec2 ndc = clip.xy / clip.w;
  ivec2 size = ivec2(frame.viewport.xy);
  int side = splat_side(c, proj, base, spacing, clip.w);
  // The side x side block of pixels whose centres are nearest the projected point.
  vec2 position = (ndc * 0.5f + 0.5f) * vec2(size);
  ivec2 first = ivec2(floor(position - 0.5f * float(side - 1)));
  uint key = hybrid_depth_key(length(q - base));
  float per_output = 1.0f / float(u_pixel_scale * u_pixel_scale);
  uint written = 0u;
  // One loop over the block, not one a row: side^2 + 1 of the loop limiter's count, not
  // (side + 1)^2 (splat_pass.cpp, splatPointCost).
  for (int k = 0; k < side * side; ++k) {
    ivec2 pixel = first + ivec2(k % side, k / side);
    if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) continue;
    // Another reflector's pixel (beside this one's silhouette): its reflection is not this one's.
    if (texelFetch(u_ids, pixel, 0).x != uint(c.counts.y)) continue;
    // Behind the visible reflector surface here: hidden by another part of the reflector.
    if (clip.w > surface_eye_depth(pixel) * (1.0f + u_occlusion)) continue;
    uint at = uint(pixel.y * size.x + pixel.x);
    if (hybrid_is_candidate(atomicMin(depths[at], key), key)) {
      uint slot = atomicAdd(counters[MIRAGE_HYBRID_COUNTER_CANDIDATES], 1u);
      if (slot < uint(u_candidate_capacity)) {
        vec2 off = vec2(pixel) + 0.5f - position;
        candidates[4u * slot] = at;
        candidates[4u * slot + 1u] = key;
        candidates[4u * slot + 2u] = hybrid_winner_word(dot(off, off) * per_output, index);
      }
    }
    ++written;
  }
  return written;
}

// What an invocation counted, added to the counters once at its end.
struct Counts {
  uint projected, projections, written, seen, facing_away;
};

// This invocation's share (every MIRAGE_HYBRID_GROUP-th) of the points [begin, end) that one
// work item takes.
void project_item(int item, ivec4 it, C3rcData c, int begin, int end, inout Counts counts) {
  // The level of detail: every stride-th point (leaves are in Morton order: a stratified
  // subsample), each standing for `stride` points, so its spacing grows by sqrt(stride).
  float stride = max(intBitsToFloat(it.w), 1.0f);
  float grown = sqrt(stride);
  // An item lies in one point cloud: one instance, its matrices and closedness loaded once.
  int instance = int(positions[it.y].w);
  mat4 model = instances[instance].model;
  mat3 linear = mat3(model);
  mat3 normal_matrix = mat3(instances[instance].normal_matrix);
  bool cull_back = u_keep_backfaces == 0 && attributes[it.y].albedo.w > 0.5f;
  uint seen = 0u;
  for (int i = begin + int(gl_LocalInvocationID.x); i < end; i += MIRAGE_HYBRID_GROUP) {
    uint index = uint(it.y + min(int(float(i) * stride), it.z - 1));
    vec4 position = positions[index], object_normal = attributes[index].normal;
    vec3 q = (model * vec4(position.xyz, 1.0f)).xyz;
    vec4 p0, p1, p2;
    int n = 0;
    bool hidden = cull_back && hybrid_faces_away(normal_matrix * object_normal.xyz, q, vec3(c.v0),
                                                 vec3(c.v1), vec3(c.v2));
    if (!hidden) n = c3rc_project(c, q, 1.0e-4f, u_first_only != 0, p0, p1, p2);
    counts.facing_away += hidden ? 1u : 0u;
    ++counts.projected;
    // Only for a point that projects: its spacing in world space, grown with the stride.
    float spacing = 0.0f;
    if (n > 0 && u_splat_size == 0)
      spacing = hybrid_world_spacing(linear, object_normal.xyz, object_normal.w) * grown;
    int splats = u_count_only != 0 ? 0 : n;
    for (int k = 0; k < splats; ++k) {
      counts.written += splat(c, k == 0 ? p0 : (k == 1 ? p1 : p2), q, spacing, index);
    }
    counts.projections += uint(n);
    seen += n > 0 ? 1u : 0u;
  }
  counts.seen += seen;
  if (u_count_only != 0 && seen > 0u) atomicAdd(item_seen[item], seen);
}

void main() {
  Counts counts = Counts(0u, 0u, 0u, 0u, 0u);
  // One run per workgroup (the host dispatches u_run_count of them in chunks the dispatch size
  // allows): a loop over runs here would multiply the invocation's loop count.
  int run = u_run_base + int(gl_WorkGroupID.x);
  if (run >= u_run_count) return;
  ivec4 r;
  if (u_slices > 0) {
    int slice = run % u_slices;
    r = ivec4(run / u_slices, slice * u_slice_points, run / u_slices, (slice + 1) * u_slice_points);
  } else {
    r = runs[run];
  }
  // A run of consecutive items (c3rc_frame.h, itemRuns): one C3RC's items are consecutive, so
  // its 320 bytes are loaded once per run, not once per item.
  int loaded = -1;
  C3rcData c;
  for (int item = r.x; item <= r.z; ++item) {
    ivec4 it = items[item];
    if (it.x != loaded) {
      c = c3rcs[it.x];
      loaded = it.x;
    }
    int taken = hybrid_taken_points(it.z, max(intBitsToFloat(it.w), 1.0f));
    int begin = item == r.x ? r.y : 0;
    int end = item == r.z ? min(r.w, taken) : taken;
    project_item(item, it, c, begin, end, counts);
  }
  atomicAdd(counters[0], counts.projected);
  atomicAdd(counters[1], counts.projections);
  atomicAdd(counters[2], counts.written);
  atomicAdd(counters[3], counts.seen);
  atomicAdd(counters[4], counts.facing_away);
}
