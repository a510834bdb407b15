// The work the impostor trace counts, per frame: the impostors each reflected ray tests (every
// billboard of its reflector's list, and every object whose depth maps it searches) and the rays
// traced, summed over the reflector pixels into atomics (MIRAGE_IMPOSTOR_*), one add of each a
// pixel. Included by the impostor methods' shaders before their hooks, which count their own
// impostors into g_impostor_candidates. It also declares the lists' direction cells.
#include "methods/impostor/billboard_shared.h"
#include "render/shaders/counter_slots.glsl"

// The counts are side effects: without early fragment tests a fragment behind the reflectors'
// depth would be shaded (and counted) before the depth test discards it.
layout(early_fragment_tests) in;

layout(std430, binding = MIRAGE_BIND_IMPOSTOR_COUNTS) buffer ImpostorCounts {
  uint impostor_counts[MIRAGE_COUNTER_SLOTS * MIRAGE_COUNTER_SLOT_WORDS];
};

// --impostor-cells: the candidate lists' direction cells a cube face edge (0: one list a
// reflector), for the billboards' lists and the hooks' own (billboard_list_index).
uniform int u_billboard_cells = 0;

int g_impostor_candidates = 0;
int g_impostor_rays = 0;

void impostor_count_pixel() {
  int slot = counter_slot();
  atomicAdd(impostor_counts[slot + MIRAGE_IMPOSTOR_CANDIDATES], uint(g_impostor_candidates));
  atomicAdd(impostor_counts[slot + MIRAGE_IMPOSTOR_RAYS], uint(g_impostor_rays));
  atomicAdd(impostor_counts[slot + MIRAGE_IMPOSTOR_PIXELS], 1u);
}
