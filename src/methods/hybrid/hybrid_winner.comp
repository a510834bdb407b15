// The hybrid method's second visibility pass (hybrid_shared.h): each candidate that the
// splatting pass appended in its pixel's final front (within MIRAGE_HYBRID_FRONT_TOLERANCE of the
// final nearest push-back) writes its winner word with atomicMin — the splat landed nearest the
// pixel's centre, ties to the lowest index, whatever the order the splats ran in.
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
  uint pixel = candidates[4u * i];
  if (hybrid_in_front(candidates[4u * i + 1u], depths[pixel]))
    atomicMin(winners[pixel], candidates[4u * i + 2u]);
}
