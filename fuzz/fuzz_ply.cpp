// libFuzzer target: fuzz_inputs.h's ply (the ply corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::ply(bytes))
