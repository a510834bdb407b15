// The GPU SRDM builder (srdm_gpu_builder.h): the same rows as buildSrdm with the greedy
// simplifier, from a depth map in a texture into the SRDM array. Two passes, chosen by a define:
//  SRDM_PASS_BOX:  the foreground's bounding box (16 x 16 texels a group, reduced in shared
//                  memory, then one atomic per group and side);
//  SRDM_PASS_ROWS: one invocation per row (64 consecutive rows of a domain a group, so that the
//                  lanes of a SIMD vector walk similar rows). Samples are not stored: each is
//                  re-read from the depth map with texelFetch whenever the greedy needs it, so a
//                  row may be as long as the map's diagonal. The row's knots and queue are
//                  private arrays of SRDM_MAX_POINTS >= m entries (the builder compiles one
//                  program per power of two): on llvmpipe the build ran up to twice as fast
//                  (m = 64) as with the same arrays in a scratch storage buffer.
#include "methods/depthmap/srdm_build_shared.h"

layout(binding = SRDM_BUILD_DEPTH_UNIT) uniform sampler2D u_depth;

uniform int u_size;  // w

layout(std430, binding = SRDM_BUILD_STATE_SSBO) buffer State {
  ivec4 box;  // x0, y0, x1, y1 (exclusive); starts as (w, w, 0, 0)
  int dropped;
}
state;

#ifdef SRDM_PASS_BOX

layout(local_size_x = SRDM_BUILD_BOX_GROUP, local_size_y = SRDM_BUILD_BOX_GROUP) in;

shared int g_box[4];

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    g_box[0] = u_size;
    g_box[1] = u_size;
    g_box[2] = 0;
    g_box[3] = 0;
  }
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x < u_size && p.y < u_size && texelFetch(u_depth, p, 0).r < 1.0f) {
    atomicMin(g_box[0], p.x);
    atomicMin(g_box[1], p.y);
    atomicMax(g_box[2], p.x + 1);
    atomicMax(g_box[3], p.y + 1);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && g_box[0] < g_box[2]) {
    atomicMin(state.box.x, g_box[0]);
    atomicMin(state.box.y, g_box[1]);
    atomicMax(state.box.z, g_box[2]);
    atomicMax(state.box.w, g_box[3]);
  }
}

#else  // SRDM_PASS_ROWS

layout(local_size_x = SRDM_BUILD_ROWS_PER_GROUP) in;

layout(binding = SRDM_BUILD_OUT_IMAGE, rgba32f) uniform writeonly image2DArray u_out;

uniform int u_domains;  // n
uniform int u_points;   // m <= SRDM_MAX_POINTS
uniform float u_k;      // (far - near) / far: relative z error factor

layout(std430, binding = SRDM_BUILD_DOMAINS_SSBO) readonly buffer Domains {
  vec4 domain_geometry[];  // cos, sin, extent, spacing (computed on the CPU, see shared)
};

// A knot of the polyline: a span's two ends sit half a sample outside its end samples. Knots are
// numbered in order of creation (span i's ends are 2 i and 2 i + 1), linked in row order.
struct Knot {
  float s, d;
  int sample_index;  // the sample it sits on (the end samples for the ends)
  int next;          // the next knot of the span, -1 after the span's last
};
Knot g_knots[SRDM_MAX_POINTS];

// A segment in the queue. Before the queue exists, the same array holds the kept spans
// (worst = first sample, left = last sample).
struct Entry {
  float error;
  int worst;    // its sample of largest error (the first such), -1 when the error is 0
  int left;     // the knot that starts it
  float depth;  // the worst sample's depth: the knot a split puts there
};
Entry g_heap[SRDM_MAX_POINTS];

// The row of this invocation.
vec2 g_a, g_start;
float g_spacing;

float sample_depth(int k) {
  ivec2 p = srdm_sample_texel(g_start, g_a, srdm_sample_s(k, g_spacing));
  bool inside = p.x >= 0 && p.y >= 0 && p.x < u_size && p.y < u_size;
  return inside ? min(texelFetch(u_depth, clamp(p, ivec2(0), ivec2(u_size - 1)), 0).r, 1.0f)
                : 1.0f;
}

// The sample of largest relative z error between knot `left` and the next (worstOfSegment).
Entry worst_of(int left) {
  Knot a = g_knots[left];
  Knot b = g_knots[a.next];
  float inv = srdm_segment_inverse(a.s, b.s);
  Entry e = Entry(0.0f, -1, left, 0.0f);
  for (int k = a.sample_index; k <= b.sample_index; ++k) {
    float d = sample_depth(k);
    float approx = srdm_segment_depth(a.s, a.d, b.d, inv, srdm_sample_s(k, g_spacing));
    float error = srdm_relative_z(u_k, approx, d);
    if (error > e.error) {
      e.error = error;
      e.worst = k;
      e.depth = d;
    }
  }
  return e;
}

// A binary max-heap under srdm_segment_above, a total order on the segments that can be split:
// its top is the CPU queue's top whatever the order of pushes.
bool above(Entry x, Entry y) { return srdm_segment_above(x.error, x.worst, y.error, y.worst); }

void heap_push(inout int size, Entry e) {
  int i = size++;
  while (i > 0) {
    int parent = (i - 1) / 2;
    Entry p = g_heap[parent];
    if (!above(e, p)) break;
    g_heap[i] = p;
    i = parent;
  }
  g_heap[i] = e;
}

void heap_replace_top(int size, Entry e) {
  int i = 0;
  for (;;) {
    int c = 2 * i + 1;
    if (c >= size) break;
    Entry ce = g_heap[c];
    if (c + 1 < size) {
      Entry r = g_heap[c + 1];
      if (above(r, ce)) {
        c = c + 1;
        ce = r;
      }
    }
    if (!above(ce, e)) break;
    g_heap[i] = ce;
    i = c;
  }
  g_heap[i] = e;
}

// Offers span [first, last] to the kept spans (heap slots 0..spans-1, in row order): the `keep`
// longest, ties to the earlier, as the CPU's stable sort. A later span replaces the shortest kept
// one (the last of the shortest) only when strictly longer.
void offer_span(int first, int last, int keep, inout int spans, inout int dropped) {
  if (spans < keep) {
    g_heap[spans++] = Entry(0.0f, first, last, 0.0f);
    return;
  }
  int shortest = -1, shortest_length = 0x7fffffff;
  for (int i = 0; i < spans; ++i) {
    Entry e = g_heap[i];
    if (e.left - e.worst <= shortest_length) {
      shortest_length = e.left - e.worst;
      shortest = i;
    }
  }
  if (last - first <= shortest_length) {
    dropped += last - first + 1;
    return;
  }
  dropped += shortest_length + 1;
  for (int i = shortest; i + 1 < spans; ++i) g_heap[i] = g_heap[i + 1];
  g_heap[spans - 1] = Entry(0.0f, first, last, 0.0f);
}

// Two points per texel, as packRow.
int g_written = 0;
vec2 g_held;
void emit(int row, int domain, vec2 point) {
  if ((g_written & 1) == 0)
    g_held = point;
  else
    imageStore(u_out, ivec3(g_written / 2, row, domain), vec4(g_held, point));
  ++g_written;
}

void main() {
  int row = int(gl_GlobalInvocationID.x);
  int domain = int(gl_GlobalInvocationID.y);
  if (row >= u_size || domain >= u_domains) return;
  vec4 geometry = domain_geometry[domain];
  g_a = vec2(geometry.x, geometry.y);
  g_spacing = geometry.w;
  float w = float(u_size);
  g_start = srdm_row_start(g_a, geometry.z, row, w);
  ivec2 range =
      srdm_row_range(g_start, g_a, state.box, geometry.z, g_spacing, srdm_sample_count(geometry.z));

  // The foreground spans over the box, at most m / 2 kept.
  int keep = u_points / 2, spans = 0, dropped = 0, run = -1;
  for (int k = range.x; k <= range.y + 1; ++k) {
    bool foreground = k <= range.y && sample_depth(k) < 1.0f;
    if (foreground && run < 0) run = k;
    if (!foreground && run >= 0) {
      offer_span(run, k - 1, keep, spans, dropped);
      run = -1;
    }
  }
  if (dropped > 0) atomicAdd(state.dropped, dropped);

  // Two knots per span, then its segment in the queue.
  float half_spacing = 0.5f * g_spacing;
  for (int i = 0; i < spans; ++i) {
    Entry span = g_heap[i];
    SRDM_EXACT float s0 = srdm_sample_s(span.worst, g_spacing) - half_spacing;
    SRDM_EXACT float s1 = srdm_sample_s(span.left, g_spacing) + half_spacing;
    g_knots[2 * i] = Knot(s0, sample_depth(span.worst), span.worst, 2 * i + 1);
    g_knots[2 * i + 1] = Knot(s1, sample_depth(span.left), span.left, -1);
  }
  int size = 0;
  for (int i = 0; i < spans; ++i) heap_push(size, worst_of(2 * i));

  // The paper's refinement: split the worst segment at its worst sample until m points.
  int count = 2 * spans;
  while (count < u_points && size > 0 && g_heap[0].error > 0.0f) {
    Entry top = g_heap[0];
    int mid = count;  // knots are numbered in order of creation
    int right = g_knots[top.left].next;
    g_knots[mid] = Knot(srdm_sample_s(top.worst, g_spacing), top.depth, top.worst, right);
    g_knots[top.left].next = mid;
    heap_replace_top(size, worst_of(top.left));
    heap_push(size, worst_of(mid));
    ++count;
  }

  // The polyline in row order, spans' first points negated; padding repeats the last point
  // (or the row's start) as span starts.
  vec2 last = vec2(0.5f, 1.0f);
  for (int i = 0; i < spans; ++i) {
    for (int n = 2 * i; n >= 0;) {
      Knot knot = g_knots[n];
      emit(row, domain, vec2(n == 2 * i ? -knot.s : knot.s, knot.d));
      last = vec2(knot.s, knot.d);
      n = knot.next;
    }
  }
  int pairs = (u_points + 1) / 2;
  while (g_written < 2 * pairs) emit(row, domain, vec2(-last.x, last.y));
}

#endif
