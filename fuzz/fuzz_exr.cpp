// libFuzzer target: fuzz_inputs.h's exr (the exr corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::exr(bytes))
