// The environment layer in the impostor methods (scene/layers.h): a room modelled as one closed
// mesh is shown through its walls as exact planar billboards, as the same walls modelled apart
// are, not as one volume billboard or depth map captured from outside it. Images against the ray
// tracer, matched 2x2; on failure the images are written under build/<preset>/test-artifacts/.
#include <gtest/gtest.h>

#include <map>

#include "methods/frame.h"
#include "scene/builtin_scenes.h"
#include "scene/procedural.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/psnr_floors.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class ImpostorLayers : public GlTest {};

// The faces of an axis-aligned box mesh as separate meshes, one per face normal.
std::vector<Mesh> facesApart(const Mesh& box) {
  std::map<std::tuple<int, int, int>, Mesh> faces;
  for (const uvec3& t : box.triangles) {
    const vec3 n = glm::cross(box.positions[t.y] - box.positions[t.x],
                              box.positions[t.z] - box.positions[t.x]);
    Mesh& face = faces[{int(glm::sign(n.x)), int(glm::sign(n.y)), int(glm::sign(n.z))}];
    uvec3 copied;
    for (int k = 0; k < 3; ++k) {
      copied[k] = uint32_t(face.positions.size());
      face.positions.push_back(box.positions[t[k]]);
      face.normals.push_back(box.normals[t[k]]);
      face.uvs.push_back(box.uvs[t[k]]);
    }
    face.triangles.push_back(copied);
  }
  std::vector<Mesh> out;
  for (auto& [key, face] : faces) out.push_back(std::move(face));
  return out;
}

// A checkered 6 x 3 x 6 room, a mirror sphere in it and two boxes; the room one mesh, or its six
// walls apart (`apart`), or one mesh the scene file puts in the object layer (`as_object`).
Scene roomWithSphere(bool apart, bool as_object = false) {
  Scene s;
  const Mesh room = procedural::box({3.0f, 1.5f, 3.0f}, true);
  const Material walls = Material::checker("walls", kCheckerLight, {0.25f, 0.35f, 0.6f}, 1.0f);
  if (apart) {
    int k = 0;
    for (Mesh& face : facesApart(room))
      addObject(s, "wall-" + std::to_string(k++), face, walls, placeAt({0.0f, 1.5f, 0.0f}));
  } else {
    addObject(s, "room", room, walls, placeAt({0.0f, 1.5f, 0.0f}));
    if (as_object) s.instances.back().layer = Layer::kObject;
  }
  addObject(s, "ball", procedural::sphere(0.6f, 96, 48), Material::mirror("chrome"),
            placeAt({0.0f, 1.0f, 0.0f}));
  addBox(s, "red-box", {1.6f, 0.4f, -1.2f}, vec3(0.4f), {0.85f, 0.2f, 0.15f}, 20.0f);
  addBox(s, "green-box", {-1.5f, 0.3f, 1.0f}, vec3(0.3f), {0.2f, 0.7f, 0.25f}, -10.0f);
  finishScene(s, {1.2f, 1.6f, 2.6f}, {0.0f, 1.0f, 0.0f}, 40.0f);
  return s;
}

TEST_F(ImpostorLayers, ARoomOfOneMeshIsSeenThroughItsWallsAsTheWallsApartAre) {
  FrameSettings settings;
  settings.order = 1;
  const ivec2 size{200, 160};
  for (const char* method : {"billboard", "depthmap"}) {
    RenderPair one = renderWithTruth(roomWithSphere(false), method, size, settings, {}, 0.0f,
                                     kMatchedSsaa);
    RenderPair apart = renderWithTruth(roomWithSphere(true), method, size, settings, {}, 0.0f,
                                       kMatchedSsaa);
    RenderPair object = renderWithTruth(roomWithSphere(false, true), method, size, settings, {},
                                        0.0f, kMatchedSsaa);
    std::printf("%s reflector PSNR: one mesh %.2f dB, walls apart %.2f dB, one object %.2f dB\n",
                method, reflectorPsnr(one), reflectorPsnr(apart), reflectorPsnr(object));
    EXPECT_TRUE(psnrAtLeast(one.gpu, one.cpu, floors::kImpostorRoomOfOneMesh, &one.cpu_ids))
        << method;
    // The walls are planar billboards either way, framed and captured alike: the same frame but
    // for float rounding (a corner computed from a part, or from a flat instance's bounds).
    EXPECT_TRUE(imagesEqual(one.gpu, apart.gpu, kFloatRounding, nullptr, std::string(method) + "-apart"))
        << method;
    // The room as an object (what every mesh was before the layers) is far worse: the rays
    // that leave the sphere meet the outside of one impostor of the whole room.
    EXPECT_GT(reflectorPsnr(one), reflectorPsnr(object) + 6.0) << method;
  }
}

}  // namespace
}  // namespace mirage::test
