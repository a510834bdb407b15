#include "methods/hybrid/c3rc_frame.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/check.h"
#include "core/timer.h"
#include "gpu/loop_budget.h"
#include "methods/hybrid/hybrid_shared.h"

namespace mirage {

namespace {

struct TriangleRef {
  int reflector;  // index into `reflectors`
  uint32_t triangle;
};

bool finite(const vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

struct Local {
  std::vector<ivec4> items;
  std::vector<uint32_t> leaves;
  CullCounters cull;
  long long degenerate = 0, multiple = 0, kept_points = 0, lod_points = 0;
};

// The stride through a C3RC's kept points that leaves about `density` per visible pixel, and at
// least `minimum` of them.
float lodStride(float density, uint32_t pixels, long long kept, long long minimum) {
  if (density <= 0.0f || kept == 0) return 1.0f;
  const double wanted = std::max(double(density) * double(pixels), double(minimum));
  return std::max(1.0f, float(double(kept) / wanted));
}

// The visible reflector triangles large enough to project (counted in `frame`).
std::vector<TriangleRef> trianglesToProject(const std::vector<std::vector<uint32_t>>& pixels,
                                            int min_pixels, C3rcFrame& frame) {
  std::vector<TriangleRef> triangles;
  for (size_t r = 0; r < pixels.size(); ++r)
    for (uint32_t t = 0; t < uint32_t(pixels[r].size()); ++t) {
      if (pixels[r][t] == 0) continue;
      ++frame.visible_triangles;
      if (int(pixels[r][t]) < min_pixels)
        ++frame.small_triangles;
      else
        triangles.push_back({int(r), t});
    }
  return triangles;
}

// A reflector triangle's world corners and normals; false for a degenerate one (no area, or
// non-finite or zero vectors), which gets no C3RC.
bool worldTriangle(const Mesh& mesh, uint32_t triangle, const mat4& model, vec3 (&v)[3],
                   vec3 (&n)[3]) {
  const mat3 normal_matrix = normalMatrix(model);
  const uvec3 tri = mesh.triangles[triangle];
  for (int k = 0; k < 3; ++k) {
    v[k] = vec3(model * vec4(mesh.positions[tri[k]], 1.0f));
    n[k] = normal_matrix * mesh.normals[tri[k]];
  }
  const float area2 = glm::length(glm::cross(v[1] - v[0], v[2] - v[0]));
  bool ok = area2 > 1e-12f && std::isfinite(area2);
  for (int k = 0; k < 3 && ok; ++k)
    ok = finite(v[k]) && finite(n[k]) && glm::dot(n[k], n[k]) > 0.0f;
  return ok;
}

// The work items of C3RC `c3rc` over one cloud: the leaves its object-space C3RC keeps, with
// neighbouring leaves (contiguous ranges of the cloud) merged into one longer item, which the
// splatting shader runs with fewer idle invocations.
void addCloudItems(int c3rc, const PointCloud& cloud, const C3rcData& in_object, Culling culling,
                   bool cull_backfaces, Local& local) {
  local.leaves.clear();
  cullLeaves(cloud.tree, in_object, culling,
             cull_backfaces ? std::span<const vec4>(cloud.cones) : std::span<const vec4>(),
             local.leaves, local.cull);
  std::sort(local.leaves.begin(), local.leaves.end(), [&](uint32_t a, uint32_t b) {
    return cloud.tree.nodes()[a].begin < cloud.tree.nodes()[b].begin;
  });
  uint32_t run_begin = 0, run_end = 0;
  auto flush = [&] {
    if (run_end == run_begin) return;
    local.items.push_back(ivec4(c3rc, int(cloud.offset + run_begin), int(run_end - run_begin), 0));
  };
  for (uint32_t leaf : local.leaves) {
    const KdNode& node = cloud.tree.nodes()[leaf];
    if (node.begin != run_end || run_end - run_begin >= kMaxItemPoints) {
      flush();
      run_begin = node.begin;
    }
    run_end = node.end;
  }
  flush();
}

// The level-of-detail stride of the items from `first_item` on (one C3RC's), from its pixels.
void setLodStride(Local& local, size_t first_item, float density, long long minimum,
                  uint32_t pixels) {
  long long kept = 0;
  for (size_t k = first_item; k < local.items.size(); ++k) kept += local.items[k].z;
  const float stride = lodStride(density, pixels, kept, minimum);
  for (size_t k = first_item; k < local.items.size(); ++k) {
    local.items[k].w = std::bit_cast<int>(stride);
    local.lod_points += shading::hybrid_taken_points(local.items[k].z, stride);
  }
  local.kept_points += kept;
}

}  // namespace

namespace {

long long takenPoints(const ivec4& item) {
  return shading::hybrid_taken_points(item.z, std::bit_cast<float>(item.w));
}

// One item's share of a run's count: its iteration of the item loop and its point loop, the
// first lane taking ceil(points / lanes) of them.
long long itemLoopCost(long long points, long long point_cost, int lanes) {
  return 1 + gpu::loopCost((points + lanes - 1) / lanes, point_cost);
}

}  // namespace

long long runLoopCost(const std::vector<ivec4>& items, const SplatRun& run, long long point_cost,
                      int lanes) {
  long long cost = 1;  // the item loop's last test
  for (int i = run.x; i <= run.z; ++i) {
    const long long begin = i == run.x ? run.y : 0;
    const long long end = i == run.z ? std::min<long long>(run.w, takenPoints(items[size_t(i)]))
                                     : takenPoints(items[size_t(i)]);
    cost += itemLoopCost(end - begin, point_cost, lanes);
  }
  return cost;
}

std::vector<SplatRun> itemRuns(const std::vector<ivec4>& items, const RunLimits& limits) {
  // The most points one item's part of a run may take with `left` of the budget (itemLoopCost).
  const auto fitting = [&](long long left) {
    return std::max<long long>((left - 2) / (1 + limits.point_cost), 0) * limits.lanes;
  };
  MIRAGE_CHECK_GT(fitting(limits.budget - 1), 0);  // a run takes at least a step of points
  std::vector<SplatRun> runs;
  long long cost = 0;  // of the open run
  size_t count = 0;    // its items
  bool open = false;
  for (size_t i = 0; i < items.size(); ++i) {
    const long long taken = takenPoints(items[i]);
    long long begin = 0;
    while (true) {
      if (!open || count >= limits.max_items || fitting(limits.budget - cost) == 0) {
        runs.push_back(SplatRun(int(i), int(begin), int(i), int(begin)));
        cost = 1;  // the item loop's last test
        count = 0;
        open = true;
      }
      const long long end = std::min(taken, begin + fitting(limits.budget - cost));
      runs.back().z = int(i);
      runs.back().w = int(end);
      cost += itemLoopCost(end - begin, limits.point_cost, limits.lanes);
      ++count;
      begin = end;
      if (begin >= taken) break;
      open = false;  // the rest of a split item starts the next run
    }
  }
  return runs;
}

void restrideByProjections(C3rcFrame& frame, std::span<const uint32_t> seen, float density) {
  MIRAGE_CHECK_EQ(seen.size(), frame.items.size());
  std::vector<ivec4> items;
  items.reserve(frame.items.size());
  frame.lod_points = 0;
  frame.dropped_c3rcs = 0;
  frame.dropped_items = 0;
  for (size_t a = 0; a < frame.items.size();) {
    const int c = frame.items[a].x;
    size_t b = a;
    long long kept = 0, probed = 0, hits = 0;
    for (; b < frame.items.size() && frame.items[b].x == c; ++b) {
      kept += frame.items[b].z;
      probed += takenPoints(frame.items[b]);
      hits += seen[b];
    }
    // The projecting fraction the probe found (half a point where it found none: a few probes
    // say little), the stride that takes `density` points with a projection a pixel.
    const double fraction = std::max(double(hits), 0.5) / double(std::max<long long>(probed, 1));
    const float stride = std::max(
        1.0f, float(double(kept) * fraction / (double(density) * double(frame.pixels[size_t(c)]))));
    const size_t before = items.size();
    for (size_t k = a; k < b; ++k) {
      // An item whose every point the probe took, none with a projection: nothing of it shows.
      // (One the probe only sampled is kept whatever it found: a run of 4,096 points of which a
      // few project is missed by its few probes, and those few are an object's thin parts.)
      if (seen[k] == 0 && takenPoints(frame.items[k]) >= frame.items[k].z) {
        ++frame.dropped_items;
        continue;
      }
      ivec4 item = frame.items[k];
      item.w = std::bit_cast<int>(stride);
      frame.lod_points += takenPoints(item);
      items.push_back(item);
    }
    if (items.size() == before) ++frame.dropped_c3rcs;
    a = b;
  }
  frame.items = std::move(items);
}

C3rcFrame buildC3rcFrame(const Scene& scene, const std::vector<int>& reflectors,
                         const std::vector<std::vector<uint32_t>>& pixels,
                         const std::vector<mat4>& matrices, const vec3& eye,
                         const PointStore& points, const C3rcFrameOptions& options,
                         const std::vector<const Mesh*>* meshes) {
  MIRAGE_CHECK_EQ(pixels.size(), reflectors.size());  // a pixel count per reflector triangle
  MIRAGE_CHECK_EQ(matrices.size(), scene.instances.size());
  Stopwatch watch;
  C3rcFrame frame;
  const std::vector<TriangleRef> triangles = trianglesToProject(pixels, options.min_pixels, frame);
  // Each cloud's world -> object map: the query moves, the tree stays.
  std::vector<mat4> to_object;
  for (const PointCloud& c : points.clouds())
    to_object.push_back(glm::inverse(matrices[size_t(c.points.instance)]));

  frame.c3rcs.resize(triangles.size());
  frame.pixels.resize(triangles.size());
  tbb::enumerable_thread_specific<Local> locals;
  tbb::parallel_for(size_t(0), triangles.size(), [&](size_t i) {
    Local& local = locals.local();
    const TriangleRef ref = triangles[i];
    const int instance = reflectors[size_t(ref.reflector)];
    const Mesh& mesh = meshes ? *(*meshes)[size_t(instance)]
                              : scene.meshes[size_t(scene.instances[size_t(instance)].mesh)];
    vec3 v[3], n[3];
    if (!worldTriangle(mesh, ref.triangle, matrices[size_t(instance)], v, n)) {
      ++local.degenerate;
      frame.c3rcs[i] = C3rcData{};  // never referenced by an item
      frame.c3rcs[i].info.z = float(MIRAGE_C3RC_DEGENERATE);
      return;
    }
    C3rcData c = reflectorC3rc(eye, v, n, options.reach, options.eye_scaled);
    c.counts.y = instance + 1;  // the triangle-ID image's word: its splats land on it only
    frame.c3rcs[i] = c;
    frame.pixels[i] = pixels[size_t(ref.reflector)][ref.triangle];
    if (int(c.info.z) & MIRAGE_C3RC_MULTIPLE) ++local.multiple;
    const size_t first_item = local.items.size();
    for (size_t k = 0; options.cull_on_cpu && k < points.clouds().size(); ++k)
      addCloudItems(int(i), points.clouds()[k], transformC3rc(c, to_object[k]), options.culling,
                    options.cull_backfaces, local);
    setLodStride(local, first_item, options.lod_density, options.lod_minimum,
                 pixels[size_t(ref.reflector)][ref.triangle]);
  });
  for (Local& local : locals) {
    frame.items.insert(frame.items.end(), local.items.begin(), local.items.end());
    frame.cull += local.cull;
    frame.degenerate_triangles += local.degenerate;
    frame.multiple_c3rcs += local.multiple;
    frame.kept_points += local.kept_points;
    frame.lod_points += local.lod_points;
  }
  frame.ms = watch.ms();
  return frame;
}

}  // namespace mirage
