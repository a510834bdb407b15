// libFuzzer target: fuzz_inputs.h's gltf (the gltf corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::gltf(bytes))
