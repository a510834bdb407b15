// The one translation unit holding tinygltf's implementation (see gltf_model.h for why mirage
// compiles its own copy).
#define TINYGLTF_IMPLEMENTATION
#include "scene/gltf_model.h"
