#include "methods/impostor/billboard_set.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "methods/impostor/candidate_cells.h"

namespace mirage {

namespace {

// A square billboard through `centre`, facing `towards` (unit, from the centre to the capture
// camera), captured by a camera of `fov` degrees at `distance`, with the camera's up near
// `up_hint`. Its half-size is the camera's half-width at the centre.
BillboardSpec facingBillboard(const vec3& centre, const vec3& towards, float distance, float fov,
                              float near_plane, float far_plane, const vec3& up_hint) {
  BillboardSpec b;
  b.camera.name = "billboard";
  b.camera.position = centre + towards * distance;
  b.camera.target = centre;
  b.camera.up = std::abs(glm::dot(up_hint, towards)) > 0.95f
                    ? (std::abs(towards.y) > 0.9f ? vec3(0, 0, -1) : vec3(0, 1, 0))
                    : up_hint;
  b.camera.fov_y_degrees = fov;
  b.camera.near_plane = near_plane;
  b.camera.far_plane = far_plane;
  const View view(b.camera, {1, 1});
  const float half = distance * std::tan(glm::radians(fov) * 0.5f);
  b.corner = centre - half * view.right() - half * view.up();
  b.edge_u = 2.0f * half * view.right();
  b.edge_v = 2.0f * half * view.up();
  return b;
}

// The billboard of a volume (bounding sphere centre, radius) seen from `viewer`.
BillboardSpec volumeBillboard(const vec3& centre, float radius, const vec3& viewer, float fov) {
  vec3 towards = viewer - centre;
  towards =
      glm::length(towards) > 1e-6f * (1.0f + radius) ? glm::normalize(towards) : vec3(0, 0, 1);
  radius = std::max(radius, 1e-6f);
  // The whole bounding sphere inside the cone of the camera.
  const float distance = radius / std::sin(glm::radians(fov) * 0.5f);
  return facingBillboard(centre, towards, distance, fov,
                         std::max(distance - 1.01f * radius, 1e-4f * distance),
                         distance + 1.01f * radius, vec3(0, 1, 0));
}

// The reflectors' bounding spheres (the viewpoints of their billboards) and their centroid.
struct ReflectorSpheres {
  std::vector<int> instances;
  std::vector<vec3> centre;
  std::vector<float> radius;
  std::vector<vec4> plane;  // a planar reflector's (unit normal, offset); 0 for a curved one
  std::vector<BoundingSphere> vertices;  // around the centre, every vertex: where rays start
  vec3 centroid{0.0f};
};

ReflectorSpheres reflectorSpheres(const Scene& scene, float time) {
  ReflectorSpheres r;
  r.instances = scene.reflectorInstances();
  const size_t count = r.instances.size();
  r.centre.assign(count, vec3(0.0f));
  r.radius.assign(count, 0.0f);
  for (size_t k = 0; k < count; ++k) {
    Bounds3 b = scene.instanceBounds(r.instances[k], time);
    r.centre[k] = b.center();
    r.radius[k] = b.radius();
    r.vertices.push_back(vertexSphere(scene, r.instances[k], time));
    r.centroid += b.center() / float(count);
    vec3 n(0.0f), point(0.0f), normal(0.0f);
    const mat4 m = scene.instances[size_t(r.instances[k])].matrixAt(time);
    r.plane.push_back(vec4(0.0f));
    if (isPlanarInstance(scene, r.instances[k], m, &n) &&
        planarInstancePlane(scene, r.instances[k], m, b.center() + n, point, normal))
      r.plane.back() = vec4(normal, glm::dot(normal, point));
  }
  return r;
}

// A billboard of reflector r's list, with the sphere bounding what it stands for and the one
// bounding where its alpha test passes.
struct ListedBillboard {
  int index;
  vec3 centre;
  float radius;
  BoundingSphere covered;
};

// Where the alpha test of billboard `spec` (framing `object`) passes.
BoundingSphere coveredBy(const BillboardSpec& spec, const BoundingSphere& object, int texels) {
  return coveredSphere(object, glm::length(spec.camera.position - object.centre),
                       glm::length(spec.edge_u) / float(std::max(texels, 1)));
}

// A planar billboard's quad: its alpha test passes inside it.
BoundingSphere quadSphere(const BillboardSpec& spec) {
  return {spec.corner + 0.5f * (spec.edge_u + spec.edge_v),
          0.5f * glm::length(spec.edge_u + spec.edge_v) * 1.01f};
}

// Which side of `plane` a sphere lies on: 1 wholly in front (along the normal), -1 wholly
// behind, 0 across it (or no plane).
int sideOf(const vec4& plane, const vec3& centre, float radius) {
  const float signed_distance = glm::dot(vec3(plane), centre) - plane.w;
  if (vec3(plane) == vec3(0.0f)) return 0;
  return signed_distance > radius ? 1 : (signed_distance < -radius ? -1 : 0);
}

// Which billboards one list keeps: those not wholly beyond `plane` from `side` (1: the rays
// leaving along the plane's normal, -1: the others), that a ray from `origin` along a direction
// of `cone` can reach.
struct ListFilter {
  vec4 plane;
  int side;
  BoundingSphere origin;
  DirectionCone cone;
  bool keeps(const ListedBillboard& b) const {
    return sideOf(plane, b.centre, b.radius) != -side && mayReach(origin, cone, b.covered);
  }
};

// Appends the entries of one list: the diffuse billboards then the reflective ones that
// `filter` keeps; returns its range.
ivec4 appendList(BillboardSet& set, const ListFilter& filter,
                 const std::vector<ListedBillboard>& diffuse,
                 const std::vector<ListedBillboard>& reflective) {
  ivec4 range(int(set.entries.size()), 0, 0, 0);
  for (const ListedBillboard& b : diffuse)
    if (filter.keeps(b)) set.entries.push_back(b.index);
  range.y = int(set.entries.size()) - range.x;
  range.z = int(set.entries.size());
  for (const ListedBillboard& b : reflective)
    if (filter.keeps(b)) set.entries.push_back(b.index);
  range.w = int(set.entries.size()) - range.z;
  return range;
}

// A planar object's own square, captured head-on from the reflectors' side; `area` is set to
// the object's area and `normal` to its normal towards the reflectors.
BillboardSpec planarBillboard(const Scene& scene, int i, float time,
                              const ReflectorSpheres& reflectors, float fov, float& area,
                              vec3& normal) {
  const mat4 m = scene.instances[size_t(i)].matrixAt(time);
  vec3 n;
  isPlanarInstance(scene, i, m, &n);
  const Bounds3 local = scene.localBounds(i);
  const vec3 e = local.extent();
  const int thin = e.x <= e.y && e.x <= e.z ? 0 : (e.y <= e.z ? 1 : 2);
  const int a1 = (thin + 1) % 3, a2 = (thin + 2) % 3;
  vec3 axis1(0.0f), axis2(0.0f);
  axis1[a1] = e[a1];
  axis2[a2] = e[a2];
  const vec3 side1 = mat3(m) * axis1, side2 = mat3(m) * axis2;
  const vec3 centre = transformPoint(m, local.center());
  if (!reflectors.instances.empty() && glm::dot(reflectors.centroid - centre, n) < 0.0f) n = -n;
  const float half = 0.5f * std::max({glm::length(side1), glm::length(side2), 1e-6f});
  const float distance = half / std::tan(glm::radians(fov) * 0.5f);
  vec3 up = glm::length(side2) > 0.0f ? glm::normalize(side2) : vec3(0, 1, 0);
  BillboardSpec b = facingBillboard(centre, n, distance, fov, 0.5f * distance, 1.5f * distance, up);
  b.kind = BillboardSpec::Kind::kPlanar;
  b.object = i;
  area = glm::length(glm::cross(side1, side2));
  normal = n;
  return b;
}

// An environment instance's planar part (in its object space) as a billboard: a square in its
// plane holding its rectangle, captured head-on from the side its triangles face, through a
// slab so thin around the plane that the rest of the instance is not in it.
BillboardSpec planarPartBillboard(const Scene& scene, const EnvironmentPlane& plane, float time,
                                  float fov) {
  const mat4 m = scene.instances[size_t(plane.instance)].matrixAt(time);
  const PlanarPart& part = plane.part;
  const vec3 corner = transformPoint(m, part.corner);
  const vec3 u = mat3(m) * part.edge_u, v = mat3(m) * part.edge_v;
  const vec3 n = glm::normalize(normalMatrix(m) * part.normal);
  const vec3 centre = corner + 0.5f * (u + v);
  const float half = 0.5f * std::max({glm::length(u), glm::length(v), 1e-6f});
  const float distance = half / std::tan(glm::radians(fov) * 0.5f);
  // The planes are gathered to 1e-4 of the mesh's size (scene/layers.cpp): twice that holds them.
  const float slab = std::max(2e-4f * scene.instanceBounds(plane.instance, time).radius(),
                              1e-5f * distance);
  const vec3 up = glm::length(v) > 0.0f ? glm::normalize(v) : vec3(0, 1, 0);
  BillboardSpec b = facingBillboard(centre, n, distance, fov, distance - slab, distance + slab, up);
  b.kind = BillboardSpec::Kind::kPlanar;
  b.object = plane.instance;
  b.part = true;
  return b;
}

// The planar objects' billboards, shared by every reflector's list (their indices returned).
// The ground (for the morph) is the largest horizontal one: with its walls it forms one box,
// and it leaves the lists.
std::vector<int> addPlanarBillboards(BillboardSet& set, const Scene& scene,
                                     const BillboardedInstances& instances, float time,
                                     const BillboardSetOptions& options,
                                     const ReflectorSpheres& reflectors) {
  const std::vector<int>& planar = instances.planar;
  std::vector<int> planar_index;
  float ground_area = 0.0f;
  for (const EnvironmentPlane& part : instances.parts) {
    BillboardSpec b = planarPartBillboard(scene, part, time, options.fov_degrees);
    b.layer = set.surface_layers++;
    planar_index.push_back(int(set.billboards.size()));
    set.billboards.push_back(b);
  }
  for (int i : planar) {
    float area = 0.0f;
    vec3 n;
    BillboardSpec b = planarBillboard(scene, i, time, reflectors, options.fov_degrees, area, n);
    b.layer = set.surface_layers++;
    if (options.morph_height > 0.0f && std::abs(n.y) > 0.99f && area > ground_area) {
      ground_area = area;
      set.ground = int(set.billboards.size());
    }
    planar_index.push_back(int(set.billboards.size()));
    set.billboards.push_back(b);
  }
  if (set.ground >= 0) {
    const BillboardSpec& g = set.billboards[size_t(set.ground)];
    const Bounds3 gb = scene.instanceBounds(g.object, time);
    set.morph_box.lo = vec3(gb.lo.x, gb.center().y, gb.lo.z);
    set.morph_box.hi = vec3(gb.hi.x, gb.center().y + options.morph_height, gb.hi.z);
    planar_index.erase(std::find(planar_index.begin(), planar_index.end(), set.ground));
  }
  return planar_index;
}

// What every reflector's lists are made of: the planar billboards (shared), the groups of
// objects (a billboard each per reflector) with the spheres around their vertices, and the
// reflectors.
struct ListSources {
  const std::vector<int>& planar_index;
  const std::vector<std::vector<int>>& groups;
  std::vector<BoundingSphere> group_vertices;
  const ReflectorSpheres& reflectors;
};

// The sphere around the vertices of a group's members, centred on their bounds' centre.
BoundingSphere groupVertexSphere(const Scene& scene, const std::vector<int>& group, float time) {
  Bounds3 b;
  for (int i : group) b.extend(scene.instanceBounds(i, time));
  BoundingSphere s{b.center(), 0.0f};
  for (int i : group) {
    const BoundingSphere member = vertexSphere(scene, i, time);
    s.radius = std::max(s.radius, glm::length(member.centre - s.centre) + member.radius);
  }
  return s;
}

// Reflector r's lists, one per direction cell (and side of a planar reflector's plane),
// each without what its rays cannot reach (ListFilter).
void appendCellLists(BillboardSet& set, int r, const ListSources& sources, bool sides,
                     const std::vector<ListedBillboard>& diffuse,
                     const std::vector<ListedBillboard>& reflective) {
  const vec4 plane = sides ? sources.reflectors.plane[size_t(r)] : vec4(0.0f);
  const BoundingSphere origin = sources.reflectors.vertices[size_t(r)];
  const int cells = shading::direction_cell_count(set.cells);
  for (int cell = 0; cell < cells; ++cell) {
    const DirectionCone cone = directionCellCone(cell, set.cells);
    shading::BillboardRange& lists = set.ranges[size_t(r * cells + cell)];
    lists.plane = plane;
    lists.range = appendList(set, {plane, 1, origin, cone}, diffuse, reflective);
    lists.back = plane == vec4(0.0f)
                     ? lists.range
                     : appendList(set, {plane, -1, origin, cone}, diffuse, reflective);
  }
}

// Reflector r's billboards and lists: the shared planar billboards, its own group billboards,
// then the reflective billboards of the other reflectors, all seen from its centre.
void addReflectorList(BillboardSet& set, int r, const Scene& scene, const ListSources& sources,
                      float time, const BillboardSetOptions& options) {
  const ReflectorSpheres& reflectors = sources.reflectors;
  const vec3 viewer = reflectors.centre[size_t(r)];
  std::vector<ListedBillboard> diffuse, reflective;
  for (int index : sources.planar_index) {
    const BillboardSpec& spec = set.billboards[size_t(index)];
    const BoundingSphere quad = quadSphere(spec);
    if (spec.part) {
      diffuse.push_back({index, quad.centre, quad.radius, quad});
      continue;
    }
    const Bounds3 b = scene.instanceBounds(spec.object, time);
    diffuse.push_back({index, b.center(), b.radius(), quad});
  }
  for (size_t g = 0; g < sources.groups.size(); ++g) {
    const std::vector<int>& group = sources.groups[g];
    Bounds3 b;
    for (int i : group) b.extend(scene.instanceBounds(i, time));
    BillboardSpec spec = volumeBillboard(b.center(), b.radius(), viewer, options.fov_degrees);
    spec.kind = BillboardSpec::Kind::kObject;
    spec.object = group.front();
    spec.members.assign(group.begin() + 1, group.end());
    spec.reflector = r;
    spec.layer = set.surface_layers++;
    diffuse.push_back({int(set.billboards.size()), b.center(), b.radius(),
                       coveredBy(spec, sources.group_vertices[g], options.texels)});
    set.billboards.push_back(spec);
  }
  for (int k = 0; k < int(reflectors.instances.size()); ++k) {
    if (k == r) continue;
    const vec3 centre = reflectors.centre[size_t(k)];
    const float radius = reflectors.radius[size_t(k)];
    BillboardSpec spec = volumeBillboard(centre, radius, viewer, options.fov_degrees);
    spec.kind = BillboardSpec::Kind::kReflective;
    spec.object = reflectors.instances[size_t(k)];
    spec.reflector = r;
    spec.represents = k;
    spec.layer = set.surface_layers++;
    spec.position_layer = set.position_layers++;
    reflective.push_back({int(set.billboards.size()), centre, radius,
                          coveredBy(spec, reflectors.vertices[size_t(k)], options.texels)});
    set.billboards.push_back(spec);
  }
  appendCellLists(set, r, sources, options.sides, diffuse, reflective);
}

}  // namespace

BillboardedInstances billboardedInstances(const Scene& scene, const BillboardSetOptions& options,
                                          float time) {
  BillboardedInstances out;
  for (int i = 0; i < int(scene.instances.size()); ++i) {
    if (scene.isReflector(i)) continue;
    if (std::find(options.excluded.begin(), options.excluded.end(), i) != options.excluded.end())
      continue;
    const bool flat = isPlanarInstance(scene, i, scene.instances[size_t(i)].matrixAt(time));
    const SceneLayers& layers = options.layers;
    if (!flat && !layers.instances.empty() && layers.environment(i)) {
      for (const EnvironmentPlane& p : layers.planes)
        if (p.instance == i) out.parts.push_back(p);
      if (std::find(layers.rest.begin(), layers.rest.end(), i) != layers.rest.end())
        out.unbillboarded.push_back(i);
      continue;
    }
    if (flat)
      out.planar.push_back(i);
    else
      (options.objects ? out.objects : out.unbillboarded).push_back(i);
  }
  return out;
}

BillboardSet placeBillboards(const Scene& scene, float time, const BillboardSetOptions& options) {
  BillboardSet set;
  const ReflectorSpheres reflectors = reflectorSpheres(scene, time);
  set.environment_centre = reflectors.centroid;
  BillboardedInstances instances = billboardedInstances(scene, options, time);
  set.unbillboarded = std::move(instances.unbillboarded);
  std::vector<std::vector<int>> groups;
  if (options.objects) groups = options.groups;
  if (groups.empty())
    for (int i : instances.objects) groups.push_back({i});
  const std::vector<int> planar_index =
      addPlanarBillboards(set, scene, instances, time, options, reflectors);
  set.cells = std::max(options.cells, 0);
  set.ranges.resize(reflectors.instances.size() * size_t(shading::direction_cell_count(set.cells)));
  ListSources sources{planar_index, groups, {}, reflectors};
  for (const std::vector<int>& group : groups)
    sources.group_vertices.push_back(groupVertexSphere(scene, group, time));
  for (int r = 0; r < int(reflectors.instances.size()); ++r)
    addReflectorList(set, r, scene, sources, time, options);
  return set;
}

std::vector<int> BillboardSet::environmentInstances() const {
  std::vector<int> instances = unbillboarded;
  if (ground >= 0) instances.push_back(billboards[size_t(ground)].object);
  return instances;
}

std::vector<shading::BillboardData> BillboardSet::gpuData(const Scene& scene) const {
  std::vector<shading::BillboardData> data;
  data.reserve(billboards.size());
  for (const BillboardSpec& b : billboards) {
    const bool reflective = b.kind == BillboardSpec::Kind::kReflective;
    shading::BillboardData d = shading::make_billboard(
        b.corner, b.edge_u, b.edge_v,
        ivec4(reflective ? MIRAGE_BILLBOARD_REFLECTIVE : MIRAGE_BILLBOARD_DIFFUSE, b.layer,
              reflective ? b.represents : -1,
              reflective ? scene.instances[size_t(b.object)].material : -1));
    d.corner.w = float(b.position_layer);
    data.push_back(d);
  }
  return data;
}

std::vector<shading::BillboardCarry> BillboardSet::carryData() const {
  std::vector<shading::BillboardCarry> out;
  out.reserve(billboards.size());
  for (const BillboardSpec& b : billboards) {
    const mat4 rows = glm::transpose(b.carry);  // rows[i]: row i of the affine map
    const mat3 normal = glm::transpose(normalMatrix(b.carry));
    out.push_back({rows[0], rows[1], rows[2], vec4(normal[0], 0.0f), vec4(normal[1], 0.0f),
                   vec4(normal[2], 0.0f)});
  }
  return out;
}

}  // namespace mirage
