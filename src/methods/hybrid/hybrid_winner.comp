// The hybrid method's second visibility pass (hybrid_shared.h): each candidate that the
// splatting pass appended at its pixel's final nearest depth writes its point index into the
// pixel's winner word with atomicMin — the nearest point, ties to the lowest index, whatever the
// order the splats ran in.
#include "methods/hybrid/hybrid_shared.h"

layout(local_size_x = MIRAGE_HYBRID_WINNER_GROUP) in;

layout(std430, binding = MIRAGE_BIND_HYBRID_SPLATS) readonly buffer DepthBlock { uint depths[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_WINNERS) buffer WinnerBlock { uint winners[]; };
layout(std430, binding = MIRAGE_BIND_HYBRID_CANDIDATES) readonly buffer CandidateBlock {
  uint candidates[];
};

uniform int u_candidate_count;

void main() {
  uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * MIRAGE_HYBRID_WINNER_GROUP +
           gl_LocalInvocationID.x;
  if (i >= uint(u_candidate_count)) return;
  uint pixel = candidates[3u * i];
  if (depths[pixel] == candidates[3u * i + 1u]) atomicMin(winners[pixel], candidates[3u * i + 2u]);
}
