// What the built-in scenes' builders share beyond builtin_scenes.h: cameras and rotations. Internal
// to scene/ (builtin_scenes.cpp and the builders in files of their own).
#pragma once

#include <vector>

#include "scene/builtin_scenes.h"

namespace mirage {

// The scene's camera "main", looking from `position` at `target`.
void addMainCamera(Scene& s, vec3 position, vec3 target, float fov_y_degrees);
// The scene's camera "walk": keyframes of position and target (core/camera_path), a recorded walk
// that `mirage compare --path-frames` measures frame by frame.
void addWalkCamera(Scene& s, std::vector<CameraKey> keys, float fov_y_degrees);
// The lathe profile (radius, y) of a spherical cap of radius 1 whose rim lies `rim_degrees` from
// its axis, in `rings` rings: the inside of the cap, y = 0 at its centre, faces +Y.
std::vector<vec2> capProfile(float rim_degrees, int rings);
quat rotationX(float degrees);
quat rotationY(float degrees);
quat rotationZ(float degrees);

// The built-in scene `gallery` (gallery_scene.cpp).
Scene galleryScene(const SceneOptions& options);
// The built-in scene `plaza` (plaza_scene.cpp).
Scene plazaScene(const SceneOptions& options);

}  // namespace mirage
