// libFuzzer target: fuzz_inputs.h's eventScript (the event_script corpus).
#include "fuzz/fuzz_common.h"
#include "fuzz/fuzz_inputs.h"

MIRAGE_FUZZ_TARGET(mirage::fuzz::eventScript(bytes))
