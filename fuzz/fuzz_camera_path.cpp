// libFuzzer target: fuzz_inputs.h's cameraPath (the camera_path corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::cameraPath(bytes))
