// libFuzzer target: fuzz_inputs.h's hdr (the hdr corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::hdr(bytes))
