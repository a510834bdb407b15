// The backward phase of one frame (the hybrid paper, §3.2 and §5): a C3RC for every reflector
// triangle that shows at least `min_pixels` pixels, each culled against every point cloud's
// kd-tree (in the cloud's object space), giving the work items of the splatting pass — one per
// (C3RC, surviving leaf). Runs on the CPU over TBB.
#pragma once

#include <span>
#include <vector>

#include "core/camera.h"
#include "methods/hybrid/c3rc_cull.h"
#include "methods/hybrid/point_store.h"
#include "scene/scene.h"

namespace mirage {

// The longest run of points one work item covers (a longer one would leave the GPU's other
// workgroups idle), and the most points a run of items takes (itemRuns).
inline constexpr uint32_t kMaxItemPoints = 4096;

struct C3rcFrameOptions {
  int min_pixels = 1;  // reflector triangles with fewer visible pixels show the environment
  Culling culling = Culling::kInner;
  // Drop the kd-nodes whose points all face away from the triangle (normal_cone.h): set where the
  // splatting skips such points (--hybrid-backfaces cull).
  bool cull_backfaces = false;
  float reach = 1.0f;      // the largest reflector-to-point distance worth searching
  bool eye_scaled = true;  // construction rays scaled by the eye distance (else unit: the paper)
  // Level of detail: at most this many points per visible pixel of a C3RC's triangle are
  // projected (a uniform stride through its kept leaves, whose splats grow to match); 0: all.
  float lod_density = 0.0f;
  long long lod_minimum = 0;  // and at least this many points a C3RC (the probe's: see below)

  // false: the C3RCs only, no items (the GPU culls them: kd_gpu_cull.h).
  bool cull_on_cpu = true;
};

struct C3rcFrame {
  std::vector<C3rcData> c3rcs;   // world space
  std::vector<uint32_t> pixels;  // the visible pixels of each C3RC's triangle
  // C3RC, first point (shared buffer), point count, the stride through them (float bits, ≥ 1)
  std::vector<ivec4> items;
  long long lod_points = 0;            // points the items take (the strides applied)
  long long kept_points = 0;           // points in the kept leaves
  long long visible_triangles = 0;     // triangles with at least one visible pixel
  long long small_triangles = 0;       // visible, but below min_pixels: environment instead
  long long degenerate_triangles = 0;  // zero area or non-finite: skipped
  long long multiple_c3rcs = 0;        // C3RCs whose sidedness allows a second projection
  long long dropped_c3rcs = 0;  // C3RCs left without items by the probe (restrideByProjections)
  long long dropped_items = 0;  // items whose every point the probe took, none projecting
  CullCounters cull;
  double ms = 0.0;  // wall time of the whole phase
};

// A run of consecutive work items that one workgroup of the splatting pass projects
// (hybrid_splat.comp): items x..z, from point y of item x's taken points (the strides applied)
// to point w of item z's (exclusive; an item's whole count where it ends inside the run).
using SplatRun = ivec4;

// What a run may cost: each point's worst case in the loop limiter's count (gpu/loop_budget.h;
// SplatPass::pointCost), the budget, the most items a run takes, the invocations sharing an item's
// points.
struct RunLimits {
  long long point_cost = 0;
  long long budget = 0;
  size_t max_items = 1;
  int lanes = 8;
};

// The runs covering every item's taken points once, in order, each within `limits`: greedy, an
// item that does not fit whole split across runs. One C3RC's items are consecutive, so a run
// loads its C3RC once.
std::vector<SplatRun> itemRuns(const std::vector<ivec4>& items, const RunLimits& limits);

// The worst case of `run` in the loop limiter's count: its loop over items, each item's loop over
// its points (lanes points a step), `point_cost` each.
long long runLoopCost(const std::vector<ivec4>& items, const SplatRun& run, long long point_cost,
                      int lanes);

// The level of detail by what can show: given each item's taken points with a projection (a probe
// pass of the splatting, `seen`), strides that take `density` such points a visible pixel of a
// C3RC's triangle (the projecting fraction the probe found over the C3RC's items, applied to its
// kept points), and no item whose every point the probe took and found none with a projection.
// Items of one C3RC are consecutive.
void restrideByProjections(C3rcFrame& frame, std::span<const uint32_t> seen, float density);
// The probe's points a C3RC at least: its projecting fraction is read from them (a thin object,
// glass's straw, can hide among fewer).
inline constexpr long long kProbeMinimum = 64;

// `pixels[r][t]`: visible pixels of triangle t of reflector instance `reflectors[r]`;
// `matrices`: every instance's current transform; `meshes` (when given): every instance's
// current mesh (a deforming reflector's shape now), else the scene's meshes.
C3rcFrame buildC3rcFrame(const Scene& scene, const std::vector<int>& reflectors,
                         const std::vector<std::vector<uint32_t>>& pixels,
                         const std::vector<mat4>& matrices, const vec3& eye,
                         const PointStore& points, const C3rcFrameOptions& options,
                         const std::vector<const Mesh*>* meshes = nullptr);

}  // namespace mirage
