// libFuzzer target: fuzz_inputs.h's sceneJson (the scene_json corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::sceneJson(bytes))
