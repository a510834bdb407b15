// tinygltf, compiled into mirage under a namespace of its own.
//
// Why not Debian's libtinygltf: libdraco.so.7, which assimp pulls in (for Draco-compressed glTF),
// exports a second, Draco-enabled build of tinygltf with the very same symbol names but other
// struct layouts. Whichever library the dynamic linker meets first serves every tinygltf call,
// and with assimp linked that is libdraco: loading a .glb then corrupted the heap (freeing a
// tinygltf::Model built by the other copy). Renaming the namespace makes our copy unambiguous.
//
// Include this header, never <tiny_gltf.h> directly, and write `tinygltf::` as usual.
#pragma once

// Images are decoded by readImageFromMemory (core/image.h), not by tinygltf's stb copy.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define tinygltf mirage_tinygltf
#include <tiny_gltf.h>
